// Chapter 1.2.2 on the CPU, in double precision: a sum of directional sines over the plane.
//
//   h(x, z, t) = sum_i a_i sin(d_i . (x, z) w_i - t phi_i),   d_i = (cos alpha_i, sin alpha_i)
//
// with w and phi as in step01 (2 pi / wavelength, speed * 2 pi / wavelength): the crests of wave i
// travel along +d_i at `speed` (the notes' + t phi sends them along -d_i). This is the
// reference that the vertex shader's displaced positions are tested against.
#pragma once

#include "step01_sine2d/sine_sum.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace step02 {

using step01::kTwoPi;

struct DirectionalWave {
    double direction_deg = 0;  // angle of d in the x-z plane, 0 = +x; crests travel along +d
    double wavelength = 1;     // metres
    double amplitude = 0;      // metres
    double speed = 0;          // metres per second (towards +d for speed > 0, as in step01)
};

struct Direction { double x, z; };

inline Direction direction(const DirectionalWave& wave) {
    const double theta = wave.direction_deg * kTwoPi / 360.0;  // the README's alpha, in radians
    return {std::cos(theta), std::sin(theta)};
}

inline double angular_wavenumber(const DirectionalWave& wave) { return kTwoPi / wave.wavelength; }
inline double phase_rate(const DirectionalWave& wave) { return wave.speed * kTwoPi / wave.wavelength; }

inline double height(const std::vector<DirectionalWave>& waves, double x, double z, double time) {
    double h = 0;
    for (const auto& wave : waves) {
        const Direction d = direction(wave);
        h += wave.amplitude * std::sin((d.x * x + d.z * z) * angular_wavenumber(wave) -
                                       time * phase_rate(wave));
    }
    return h;
}

// A ring of waves spreading from the point (x, z) (ripple.glsl): its crests are circles about it, and
// they travel outwards at `speed`. Its energy per unit area, proportional to its amplitude squared,
// spreads round a circle 2 pi r long, so beyond one wavelength the amplitude falls as 1 / sqrt(r);
// `amplitude` is its value one wavelength out, which it keeps nearer in (the splash itself).
struct Ripple {
    double x = 0, z = 0;     // its centre, metres
    double wavelength = 5;   // metres
    double amplitude = 0;    // metres, one wavelength from the centre
    double speed = 0;        // metres per second, outwards
};

inline double ripple_height(const Ripple& ripple, double x, double z, double time) {
    const double r = std::hypot(x - ripple.x, z - ripple.z);
    const double w = kTwoPi / ripple.wavelength;
    const double spread = std::sqrt(ripple.wavelength / std::max(r, ripple.wavelength));
    return ripple.amplitude * spread * std::sin(r * w - time * ripple.speed * w);
}

// The flat facet shading's normal (facet.glsl): two vectors in a triangle's plane crossed,
// normalised and turned to face up (+y).
struct Vector { double x, y, z; };
inline Vector facet_normal(const Vector& a, const Vector& b) {
    Vector n{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const double sign = n.y < 0 ? -1.0 : 1.0;
    return {sign * n.x / length, sign * n.y / length, sign * n.z / length};
}

}  // namespace step02
