// ocean_maps.hpp's inverse FFT through FFTW (double): the CPU reference's FFT. A file of its own
// because FFTW is GPL: the browser build, which holds no GPL code, and a build without FFTW take
// ocean_maps_radix2.cpp instead.
#include "step05_fft/ocean_maps.hpp"

#include <fftw3.h>

namespace step05 {

ComplexField inverse_fft_2d(const ComplexField& input, int n) {
    static_assert(sizeof(Complex) == sizeof(fftw_complex), "std::complex<double> is fftw_complex");
    ComplexField output(input.size());
    ComplexField scratch = input;  // FFTW_ESTIMATE plans do not touch the input, but may not be const
    fftw_plan plan = fftw_plan_dft_2d(n, n, reinterpret_cast<fftw_complex*>(scratch.data()),
                                      reinterpret_cast<fftw_complex*>(output.data()), FFTW_BACKWARD,
                                      FFTW_ESTIMATE);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    return output;
}

}  // namespace step05
