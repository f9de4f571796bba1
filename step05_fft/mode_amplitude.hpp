// One mode's initial amplitude h0(k), in a file of its own: spectrum.cpp draws every mode with it,
// and exercise 8 hands this one function to the learner (README section 1 derives it).
#pragma once

#include <complex>

namespace step05 {

// h0(k) from two standard normal numbers xi and the mode's expected energy Phi(k) dk^2 (m^2).
std::complex<double> initial_amplitude(double xi_real, double xi_imaginary, double energy);

}  // namespace step05
