// The simulation on the CPU, fast: the FFTW backend of OceanSimulation (the chapter's own radix 2
// where a build has no FFTW: cpu_fft.hpp). The double-precision reference
// (ocean_maps.hpp) is what the tests hold every path to; this is the same evolution and the same
// transforms in single precision, laid out as the GPU's buffers are, so that one upload hands
// the GPU exactly what its own FFT would have made:
//   - the initial spectrum's per-mode factors are computed once per spectrum, in float;
//   - each frame the phase omega t is reduced modulo 2 pi in double (t may be days), then the
//     16 complex fields (4 a cascade) are formed in one pass over the modes;
//   - one CpuFft transforms all of them in place on every core (cpu_fft.hpp: FFTW's plan, planned
//     with FFTW_MEASURE once and remembered in a wisdom file beside the executable);
//   - e^{i omega t} is computed once per distinct omega: omega depends on |k| only, and the
//     square grid holds each |k| up to 8 times (+-kx, +-kz, swapped), so 8 times fewer sines;
//   - assemble() unpacks the fields into the renderer's two textures and box-filters their
//     mipmaps on the same cores, so the GPU receives finished textures (on llvmpipe its unpacking
//     pass and glGenerateMipmap cost 8 ms of a 13 ms simulation).
#pragma once

#include "step05_fft/cpu_fft.hpp"
#include "step05_fft/spectrum.hpp"

#include <complex>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace step05 {

class CpuSimulation {
public:
    // Plans the transform of `cascades` x 4 complex n x n fields. `wisdom_file` (may be empty)
    // is read before planning and written after.
    CpuSimulation(int n, int cascades, std::string wisdom_file);
    ~CpuSimulation();
    CpuSimulation(const CpuSimulation&) = delete;
    CpuSimulation& operator=(const CpuSimulation&) = delete;

    void set_spectra(const std::vector<const InitialSpectrum*>& cascades);
    // Evolves to `time` and transforms: fields() then holds cascades x 4 x n x n complex values
    // (interleaved re, im), the layout of OceanSimulation's fields buffer.
    void run(double time);
    const float* fields() const;
    std::size_t float_count() const { return std::size_t(layers_) * n_ * n_ * 2; }
    int threads() const { return threads_; }

    // The transforms alone on whatever the buffer holds, for the benchmark's floor.
    void transform_only();

    // After run(): assemble.comp's two maps, (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz,
    // l dDx/dx, l dDz/dz) with l the choppiness, and their mipmaps, each level a 2 x 2 box average
    // of the one above (what glGenerateMipmap computes).
    struct MipLevel {
        int size = 0;                              // texels per side
        std::vector<float> displacement, slopes;   // cascades x size x size x RGBA, layer major
    };
    void assemble(float choppiness);
    const std::vector<MipLevel>& levels() const { return levels_; }

private:
    struct Mode {  // one wavevector of one cascade
        std::complex<float> h0, h0_minus_conj;  // h0(k) and conj(h0(-k))
        std::uint32_t phase;                    // its omega's entry in omegas_
        float ux, uz, kx, kz;                   // k / |k| and k
    };
    void evolve_range(std::size_t begin, std::size_t end);  // modes [begin, end), phases_ ready
    void assemble_layer(int cascade, float choppiness);    // level 0 and the mipmaps of one cascade
    // Runs work(part) for part in [0, parts) on threads_ threads (this one included).
    template <class Work>
    void in_parallel(int parts, const Work& work) const;

    int n_, layers_, threads_;
    std::vector<Mode> modes_;          // cascades x n x n
    std::vector<double> omegas_;       // the distinct omegas
    std::vector<std::complex<float>> phases_;  // e^{i omega t} for each, this frame
    std::vector<MipLevel> levels_;
    CpuFft fft_;                       // the fields, cascades x 4 x n x n, and their transform
    std::complex<float>* data_;        // fft_.data()
};

}  // namespace step05
