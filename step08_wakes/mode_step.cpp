#include "step08_wakes/mode_step.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step08 {

Mode turn_mode(Mode mode, double K, double dt, Complex pressure, Complex source) {
    const double g = ocean::kGravity;
    if (K == 0)
        return {mode.eta + source * dt, mode.phi - (g * mode.eta + pressure) * dt - 0.5 * g * source * dt * dt};
    const double omega = std::sqrt(g * K), c = std::cos(omega * dt), s = std::sin(omega * dt);
    const Complex rest_eta = -pressure / g, rest_phi = -source / K;  // the constant solution
    const Complex e = mode.eta - rest_eta, f = mode.phi - rest_phi;   // what turns about it
    return {rest_eta + e * c + (K / omega) * f * s, rest_phi + f * c - (g / omega) * e * s};
}

}  // namespace step08
