// Chapter 5.5's height fog on the CPU, in double precision: fog.glsl's reference.
//
// Fog is air full of droplets, thickest near the sea: its density falls with height as
//     rho(y) = density e^{-falloff y}.
// Light from a point p reaching the eye loses the fraction 1 - e^{-tau} of itself to the fog and
// gains as much of the fog's colour, where tau, the optical depth, is the density summed along the
// segment: with eye + s (p - eye), s in [0, 1], and dy = p.y - eye.y,
//     tau = |p - eye| * integral_0^1 rho(eye.y + s dy) ds
//         = density e^{-falloff eye.y} |p - eye| (1 - e^{-falloff dy}) / (falloff dy)
// (|p - eye| density e^{-falloff eye.y} for a level ray, the limit dy -> 0).
#pragma once

#include "step03_lighting/normals.hpp"

#include <cmath>

namespace step06 {

inline double fog_optical_depth(const step03::Vec3& eye, const step03::Vec3& p, double density, double falloff) {
    const step03::Vec3 ray{p.x - eye.x, p.y - eye.y, p.z - eye.z};
    const double distance = std::sqrt(step03::dot(ray, ray));
    const double x = falloff * ray.y;
    const double along = std::abs(x) > 1e-8 ? -std::expm1(-x) / x : 1.0 - 0.5 * x;  // the mean of e^{-f s dy}
    return density * std::exp(-falloff * eye.y) * distance * along;
}

// How much of the fog's colour replaces the surface's: 1 - e^{-tau}, from 0 (clear) to 1.
inline double fog_amount(const step03::Vec3& eye, const step03::Vec3& p, double density, double falloff) {
    return -std::expm1(-fog_optical_depth(eye, p, density, falloff));
}

}  // namespace step06
