// Chapter 4.3-4.5 on the CPU, in double precision: the spectrum at time t and the eight real
// maps the renderer needs, through an inverse FFT (FFTW's, or the chapter's own radix 2 where a
// build has no FFTW). This is the reference for the GPU's DFT and FFT, and
// the third backend of the step (computed here, then uploaded).
//
//   h~(k, t) = h0(k) e^{-i omega t} + conj(h0(-k)) e^{i omega t}      (Hermitian: h is real)
//   D~  = +i k/|k| h~        (choppy displacement),   slopes i k h~,
//   dDx/dx <- -kx^2/|k| h~,  dDz/dz <- -kz^2/|k| h~,  dDx/dz <- -kx kz/|k| h~
//   field(x) = sum_k field~(k) e^{i k.x}                                (inverse DFT, no 1/N)
//
// Two signs differ from the notes (4.3, 4.5), and both matter on screen. The mode h0(k) e^{i(k.x -
// omega t)} has its crests where k.x - omega t is constant: they travel along +k, so the energy
// the spectrum puts around the wind's direction goes with the wind (the notes' e^{+i omega t}
// sends it upwind). And one mode h = A cos(theta), theta = k.x - omega t, gets D = -k/|k| A sin(theta):
// with x' = x + lambda D the points crowd towards each crest, which sharpens (a Gerstner wave, a
// trochoid for lambda = 1) while the troughs flatten; the notes' -i gives round crests and cusped,
// folding troughs.
//
// The eight real fields travel as four complex ones: if A~ and B~ are Hermitian, the inverse
// transform of A~ + i B~ is a + i b, two real fields for the price of one transform.
#pragma once

#include "step05_fft/spectrum.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace step05 {

using Complex = std::complex<double>;
using ComplexField = std::vector<Complex>;  // n*n, row (z) major, FFT layout

// The pairs packed into each complex transform (real part, imaginary part).
enum Field { Height, DisplacementX, DisplacementZ, SlopeX, SlopeZ, DDxDx, DDzDz, DDxDz, kFieldCount };
constexpr std::array<std::array<Field, 2>, 4> kPacking{{{Height, DisplacementX},
                                                        {DisplacementZ, SlopeX},
                                                        {SlopeZ, DDxDx},
                                                        {DDzDz, DDxDz}}};
const char* field_name(Field f);  // "height", "displacement_x", ...
// The maps a map view shows, in map_view.frag's order (its u_map): five of the fields, by their
// names, and the Jacobian made from the derivatives. step05's `view` lists these, as any
// program's map view can.
std::vector<std::string> map_view_names();

// The phase omega t reduced to [0, 2 pi) in double precision, as the GPU receives it (the
// rotation applied to h0(k) is then e^{-i phase}). Inline: the fragment simulation needs it and
// none of this file's CPU transforms.
inline double reduced_phase(double omega, double time) {
    const double phase = std::fmod(omega * time, 2 * ocean::kPi);
    return phase < 0 ? phase + 2 * ocean::kPi : phase;
}

// One mode (mode.glsl's evolve_mode): h0(k) e^{-i phase} + conj(h0(-k)) e^{+i phase}.
Complex evolve_mode(Complex h0_k, Complex h0_minus_k, double phase);
// One mode's four packed pairs from h~ at k = (kx, kz), kPacking's order (mode.glsl's packed_pairs);
// all zero at k = 0.
std::array<Complex, 4> packed_pairs(Complex h, double kx, double kz);

// h~(k, t) alone (Hermitian: its inverse transform is real).
ComplexField height_spectrum(const InitialSpectrum& s, double time);
// The four packed spectra at time t.
std::array<ComplexField, 4> packed_spectra(const InitialSpectrum& s, double time);

struct OceanMaps {
    int n = 0;
    double patch_size = 0;
    std::array<std::vector<double>, kFieldCount> fields;  // each n*n, x_i = i L / n, z_j = j L / n

    const std::vector<double>& operator[](Field f) const { return fields[f]; }
    // J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2 at cell `index`, for choppiness l.
    double jacobian(std::size_t index, double choppiness) const;
    // The unit normal of the choppy surface at cell `index` (ocean_maps.glsl's choppy_normal):
    // N = dP/dz x dP/dx with dP/dx = (1 + l dDx/dx, dh/dx, l dDx/dz), dP/dz = (l dDx/dz, dh/dz,
    // 1 + l dDz/dz); with l = 0, step03's normalize(-dh/dx, 1, -dh/dz).
    std::array<double, 3> normal(std::size_t index, double choppiness) const;
};

// Inverse 2D transforms of the four packed spectra (double), unpacked into 8 fields.
OceanMaps transform_cpu(const std::array<ComplexField, 4>& spectra, int n, double patch_size);
// The whole reference: evolve to t, transform.
OceanMaps simulate_cpu(const InitialSpectrum& s, double time);
// The inverse 2D DFT of one complex field, unnormalised: FFTW's (ocean_maps_fftw.cpp), or where a
// build has no FFTW the chapter's own radix 2 (ocean_maps_radix2.cpp). Also for tests on any input.
ComplexField inverse_fft_2d(const ComplexField& input, int n);


}  // namespace step05
