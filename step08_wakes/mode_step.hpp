// Chapter 8.2's step for one Fourier mode, on its own so that exercise 1 (./ocean exercise
// step08_wakes 1) can empty it: wave_field.cpp calls it for every mode of the grid.
#pragma once

#include <complex>

namespace step08 {

using Complex = std::complex<double>;

// Products written out. A general product of two std::complex calls a library routine that checks
// for infinities and NaNs (C's Annex G): several times slower than the four multiplications, in
// the FFT's inner loop and for every mode. times_i(z) = i z; times(a, b) = a b.
inline Complex times_i(Complex z) { return {-z.imag(), z.real()}; }
inline Complex times(Complex a, Complex b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// One mode's amplitudes: the height eta^ (m) and the surface potential phi^ (m^2/s).
struct Mode {
    Complex eta, phi;
};

// Advances one mode dt seconds under
//     d eta^ / dt = K phi^ + s^,    d phi^ / dt = -g eta^ - P^
// with the pressure P^ (p / rho) and the source s^ held constant over the step, exactly: turned by
// omega dt (omega = sqrt(g K)) about the constant solution (eta = -P^ / g, phi = -s^ / K). K = 0 (the
// mean level) has no restoring force: the source fills it, the pressure and gravity push phi.
Mode turn_mode(Mode mode, double K, double dt, Complex pressure, Complex source);

}  // namespace step08
