// ocean_maps.hpp's transforms through FFTW (double): the CPU reference's FFT. A file of its own
// because FFTW is GPL: the browser build, which holds no GPL code, leaves it out.
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

OceanMaps transform_fftw(const std::array<ComplexField, 4>& spectra, int n, double patch_size) {
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
    return transform_fftw(packed_spectra(s, time), s.n, s.patch_size);
}

}  // namespace step05
