#include "step05_fft/mode_amplitude.hpp"

#include <cmath>

namespace step05 {

// (xi_r + i xi_i) sqrt(E / 4): a complex Gaussian of mean square E / 2. The 1/4, not the notes' 1/2,
// because the time evolution adds conj(h0(-k)), a second copy of every mode's energy: then
// E|h(k, t)|^2 = (Phi(k) + Phi(-k)) dk^2 / 2, and the height's variance is sum Phi dk^2.
std::complex<double> initial_amplitude(double xi_real, double xi_imaginary, double energy) {
    return std::complex<double>(xi_real, xi_imaginary) * std::sqrt(energy / 4);
}

}  // namespace step05
