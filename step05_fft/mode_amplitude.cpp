#include "step05_fft/mode_amplitude.hpp"

#include <cmath>

namespace step05 {

// A mode's random start: a complex Gaussian scaled so that the sea's height variance is the
// spectrum's integral, counting the copy of every mode's energy that the time evolution adds
// with conj(h0(-k)) (README section 1; how_we_know.md has the scale).
std::complex<double> initial_amplitude(double xi_real, double xi_imaginary, double energy) {
    return std::complex<double>(xi_real, xi_imaginary) * std::sqrt(energy / 4);
}

}  // namespace step05
