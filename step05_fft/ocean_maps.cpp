#include "step05_fft/ocean_maps.hpp"

// The maps' definitions and the reference's transforms; the inverse FFT itself is FFTW's
// (ocean_maps_fftw.cpp) or, in the builds without FFTW, the chapter's own (ocean_maps_radix2.cpp).

#include <algorithm>
#include <cmath>
#include <cstring>

namespace step05 {

const char* field_name(Field f) {
    static const char* names[kFieldCount] = {"height", "displacement_x", "displacement_z", "slope_x",
                                             "slope_z", "ddx_dx", "ddz_dz", "ddx_dz"};
    return names[f];
}

std::vector<std::string> map_view_names() {
    return {field_name(Height), field_name(DisplacementX), field_name(DisplacementZ), field_name(SlopeX),
            field_name(SlopeZ), "jacobian"};
}

Complex evolve_mode(Complex h0_k, Complex h0_minus_k, double phase) {
    const Complex rotation(std::cos(phase), -std::sin(phase));  // e^{-i omega t}: along +k
    return h0_k * rotation + std::conj(h0_minus_k) * std::conj(rotation);
}

std::array<Complex, 4> packed_pairs(Complex h, double kx, double kz) {
    const double k = std::hypot(kx, kz);
    if (k == 0) return {};  // the mean level: zero
    const Complex i_unit(0, 1);
    const Complex dx = i_unit * (kx / k) * h, dz = i_unit * (kz / k) * h;  // +i: sharp crests
    const Complex sx = i_unit * kx * h, sz = i_unit * kz * h;
    // d/dx of a mode is a factor i kx: dDx/dx = i kx (i kx/|k| h~) = -kx^2/|k| h~.
    const Complex dxx = -(kx * kx / k) * h, dzz = -(kz * kz / k) * h, dxz = -(kx * kz / k) * h;
    return {h + i_unit * dx, dz + i_unit * sx, sz + i_unit * dxx, dzz + i_unit * dxz};
}

ComplexField height_spectrum(const InitialSpectrum& s, double time) {
    const int n = s.n;
    ComplexField h(std::size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t index = std::size_t(j) * n + i;
            const std::size_t minus = std::size_t((n - j) % n) * n + std::size_t((n - i) % n);
            h[index] = evolve_mode(s.h0[index], s.h0[minus], reduced_phase(s.omega[index], time));
        }
    return h;
}

std::array<ComplexField, 4> packed_spectra(const InitialSpectrum& s, double time) {
    const int n = s.n;
    std::array<ComplexField, 4> out;
    for (auto& field : out) field.assign(std::size_t(n) * n, {0, 0});
    const ComplexField heights = height_spectrum(s, time);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t index = std::size_t(j) * n + i;
            const auto pairs = packed_pairs(heights[index], wavenumber(i, n, s.patch_size), wavenumber(j, n, s.patch_size));
            for (int f = 0; f < 4; ++f) out[std::size_t(f)][index] = pairs[std::size_t(f)];
        }
    return out;
}

double OceanMaps::jacobian(std::size_t index, double choppiness) const {
    const double xx = 1 + choppiness * fields[DDxDx][index];
    const double zz = 1 + choppiness * fields[DDzDz][index];
    const double xz = choppiness * fields[DDxDz][index];
    return xx * zz - xz * xz;
}

std::array<double, 3> OceanMaps::normal(std::size_t index, double choppiness) const {
    const double xx = 1 + choppiness * fields[DDxDx][index], zz = 1 + choppiness * fields[DDzDz][index];
    const double xz = choppiness * fields[DDxDz][index];
    const double along_x[3] = {xx, fields[SlopeX][index], xz}, along_z[3] = {xz, fields[SlopeZ][index], zz};
    const std::array<double, 3> c{along_z[1] * along_x[2] - along_z[2] * along_x[1],
                                  along_z[2] * along_x[0] - along_z[0] * along_x[2],
                                  along_z[0] * along_x[1] - along_z[1] * along_x[0]};
    const double length = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (length < 1e-12) return {0.0, 1.0, 0.0};  // folded edge-on: no normal (ocean_maps.glsl's guess)
    return {c[0] / length, c[1] / length, c[2] / length};
}

OceanMaps transform_cpu(const std::array<ComplexField, 4>& spectra, int n, double patch_size) {
    OceanMaps maps;
    maps.n = n;
    maps.patch_size = patch_size;
    for (std::size_t t = 0; t < 4; ++t) {
        const ComplexField result = inverse_fft_2d(spectra[t], n);
        auto& real_part = maps.fields[kPacking[t][0]];
        auto& imaginary_part = maps.fields[kPacking[t][1]];
        real_part.resize(result.size());
        imaginary_part.resize(result.size());
        for (std::size_t i = 0; i < result.size(); ++i) {
            real_part[i] = result[i].real();
            imaginary_part[i] = result[i].imag();
        }
    }
    return maps;
}

OceanMaps simulate_cpu(const InitialSpectrum& s, double time) {
    return transform_cpu(packed_spectra(s, time), s.n, s.patch_size);
}

}  // namespace step05
