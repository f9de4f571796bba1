// One Gerstner wave in closed form (README section 4; GPU Gems 1, chapter 1), in double: the CPU
// reference of shaders/gerstner.glsl, and what `--set sea=gerstner` draws. In the maps' form, so
// that it can stand in for the FFT's sea: with theta = k d.p - phase (d the unit direction, k the
// wavenumber, phase = omega t),
//     h = A cos(theta),   D = -Q A d sin(theta)   (the point moves towards the crest ahead of it)
// and their derivatives. Q is the steepness (the FFT sea's choppiness for this one wave). The map
// p -> p + D has the Jacobian J = 1 - Q k A cos(theta): smallest at the crests, where the surface
// folds once Q k A > 1 (the fold limit; at Q k A = 1 the crest is a cusp, the trochoid).
#pragma once

#include <array>
#include <cmath>

namespace step05 {

struct GerstnerWave {
    double direction_x = 1, direction_z = 0;  // unit
    double wavenumber = 0.1;                  // rad/m
    double amplitude = 1;                     // m
    double steepness = 1;                     // Q
};

// The sample at rest position (x, z): displacement (Q Dx, h, Q Dz, Q dDx/dz) and slopes (dh/dx,
// dh/dz, Q dDx/dx, Q dDz/dz), as the FFT's maps hold them (ocean_maps.glsl).
struct MapSample {
    std::array<double, 4> displacement, slopes;
};

inline MapSample gerstner_sample(const GerstnerWave& w, double x, double z, double phase) {
    const double dx = w.direction_x, dz = w.direction_z, k = w.wavenumber, a = w.amplitude, q = w.steepness;
    const double theta = k * (dx * x + dz * z) - phase, c = std::cos(theta), s = std::sin(theta);
    MapSample m;
    m.displacement = {-q * a * dx * s, a * c, -q * a * dz * s, -q * a * k * dx * dz * c};
    m.slopes = {-a * k * dx * s, -a * k * dz * s, -q * a * k * dx * dx * c, -q * a * k * dz * dz * c};
    return m;
}

}  // namespace step05
