// Significant wave heights by hand, for the tests of step05 and of any program that uses its
// spectrum (a preset's sea): independent of the code's sums over the grid.
#pragma once

#include "step05_fft/spectrum.hpp"

#include <cmath>

namespace step05 {

// Hs = 4 sqrt(integral of the omnidirectional spectrum the sea is made from), integrated here in
// log k (midpoints, 1e-3 to 1e3 times PM's peak wavenumber, deep water): not the code's sums.
inline double spectrum_height(double wind, double fetch, double gamma, JonswapEnergy energy) {
    SpectrumParams p;
    p.wind_speed = wind, p.fetch = fetch, p.gamma = gamma, p.energy = energy, p.depth = 1e6;
    const double k_pm = std::pow(0.855 * kGravity / wind, 2) / kGravity;
    const int steps = 20000;
    const double lo = std::log(1e-3 * k_pm), hi = std::log(1e3 * k_pm), h = (hi - lo) / steps;
    double variance = 0;
    for (int i = 0; i < steps; ++i) {
        const double k = std::exp(lo + (i + 0.5) * h);
        variance += omnidirectional_k(p, k) * k * h;
    }
    return 4 * std::sqrt(variance);
}

// Pierson-Moskowitz's fully developed Hs, by hand from its alpha = 0.0081 and peak 0.855 g/U
// (U at 10 m): 4 sqrt(alpha g^2 / (5 omega_p^4)) = 4 sqrt(0.0081 / 5) / 0.855^2 U^2 / g
// = 0.160997 / 0.731025 U^2 / g = 0.220235 U^2 / g (the textbooks' 0.21 U19.5^2 / g, U19.5 = 1.026 U10).
inline double fully_developed_height(double wind) { return 0.220235 * wind * wind / kGravity; }

}  // namespace step05
