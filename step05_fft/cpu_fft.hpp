// The CPU backend's transforms (CpuSimulation): `layers` inverse 2D FFTs of n x n complex floats,
// in place, on every core. Two forms, one per build:
//   - FFTW's (cpu_fft_fftw.cpp): one plan for all the layers (fftwf_plan_many_dft), planned with
//     FFTW_MEASURE once and remembered in a wisdom file beside the executable (the first run of a
//     size measures; later runs start at once);
//   - where a build has no FFTW (the Windows cross-build), the chapter's own radix 2
//     (cpu_fft_radix2.cpp, radix2.hpp), its lines shared among the cores.
#pragma once

#include <complex>
#include <string>

namespace step05 {

class CpuFft {
public:
    // `wisdom_file` (may be empty): FFTW's plans, read before planning and written after.
    CpuFft(int n, int layers, const std::string& wisdom_file);
    ~CpuFft();
    CpuFft(const CpuFft&) = delete;
    CpuFft& operator=(const CpuFft&) = delete;

    std::complex<float>* data() const { return data_; }  // layers x n x n, zeroed at first
    void run();                                        // transforms data() in place
    int threads() const { return threads_; }
    static const char* const kName;  // "FFTW" or "radix 2", for the log and the benchmark

private:
    int n_, layers_, threads_;
    std::complex<float>* data_ = nullptr;
    void* plan_ = nullptr;  // FFTW's plan, or the radix 2's InverseFft2d<float>
};

// Where the wisdom lives: beside the running executable, in the build folder (empty if unknown).
std::string default_wisdom_file();

}  // namespace step05
