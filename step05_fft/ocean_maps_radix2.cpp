// ocean_maps.hpp's inverse FFT through the chapter's own radix 2 (radix2.hpp), in double: the CPU
// reference where a build has no FFTW (the Windows cross-build, the browser).
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/radix2.hpp"

namespace step05 {

ComplexField inverse_fft_2d(const ComplexField& input, int n) {
    ComplexField output = input;
    InverseFft2d<double>(n).field(output.data());
    return output;
}

}  // namespace step05
