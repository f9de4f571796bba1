// The simulation on the CPU, fast: the FFTW backend of GpuOcean. The double-precision reference
// (ocean_maps.hpp) is what the tests hold every path to; this is the same evolution and the same
// transforms in single precision, laid out as the GPU's buffers are, so that one upload hands
// the GPU exactly what its own FFT would have made:
//   - the initial spectrum's per-mode factors are computed once per spectrum, in float;
//   - each frame the phase omega t is reduced modulo 2 pi in double (t may be days), then the
//     16 complex fields (4 a cascade) are formed in one pass over the modes;
//   - one FFTW plan transforms all of them (fftwf_plan_many_dft, in place), with as many threads
//     as the machine has cores, planned with FFTW_MEASURE once and remembered in a wisdom file
//     beside the executable (the first run of a size measures; later runs start at once).
#pragma once

#include "step05_fft/spectrum.hpp"

#include <complex>
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
    // (interleaved re, im), the layout of GpuOcean's fields buffer.
    void run(double time);
    const float* fields() const;
    std::size_t float_count() const { return std::size_t(layers_) * n_ * n_ * 2; }
    int threads() const { return threads_; }

    // The transforms alone on whatever the buffer holds, for the benchmark's floor.
    void transform_only();

private:
    struct Mode {  // one wavevector of one cascade
        std::complex<float> h0, h0_minus_conj;  // h0(k) and conj(h0(-k))
        double omega;
        float ux, uz, kx, kz;                   // k / |k| and k
    };
    void evolve_range(double time, std::size_t begin, std::size_t end);  // modes [begin, end)

    int n_, layers_, threads_;
    std::vector<Mode> modes_;  // cascades x n x n
    std::complex<float>* data_ = nullptr;  // fftwf_malloc'd, cascades x 4 x n x n
    void* plan_ = nullptr;
};

// The process's FFTW threads: set up once (fftwf_init_threads), the count used for every plan.
int fftw_thread_count();
// Where the wisdom lives: beside the running executable, in the build folder (empty if unknown).
std::string default_wisdom_file();

}  // namespace step05
