// Chapter 2 on the CPU, in double precision: the slope of the sea and its normal.
//
//   h(x, z)   = sum_i a_i sin(d_i.(x,z) w_i - t phi_i)                    (step02)
//   dh/dx     = sum_i w_i a_i d_ix cos(d_i.(x,z) w_i - t phi_i)          same loop, same angle
//   dh/dz     = sum_i w_i a_i d_iz cos(d_i.(x,z) w_i - t phi_i)
//   T = (1, dh/dx, 0),  B = (0, dh/dz, 1),  N = normalize(B x T) = normalize(-dh/dx, 1, -dh/dz)   (y up)
//
// The notes write T = <1, 0, d/dx> and B = <0, 1, d/dz>: those are the vectors of a z-up world.
// With y up the slope goes in the y component, and N = normalize(B x T) (T x B points down into
// the water).
#pragma once

#include "step02_sine3d/waves.hpp"

#include <cmath>

namespace step03 {

using step02::DirectionalWave;

struct HeightGradient {
    double height = 0, dh_dx = 0, dh_dz = 0;
};

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 normalize(const Vec3& v) {
    const double length = std::sqrt(dot(v, v));
    return {v.x / length, v.y / length, v.z / length};
}

// The height and both partial derivatives, summed in one loop over the waves.
inline HeightGradient height_and_gradient(const std::vector<DirectionalWave>& waves, double x, double z,
                                          double time) {
    HeightGradient g;
    for (const auto& wave : waves) {
        const auto d = step02::direction(wave);
        const double w = step02::angular_wavenumber(wave);
        const double angle = (d.x * x + d.z * z) * w - time * step02::phase_rate(wave);
        g.height += wave.amplitude * std::sin(angle);
        const double slope = w * wave.amplitude * std::cos(angle);  // d/d(along d) of this wave
        g.dh_dx += slope * d.x;
        g.dh_dz += slope * d.z;
    }
    return g;
}

// The notes' slope: (h(x + s) - h(x - s)) / (2 s) along each axis (it uses s = 1). Costs four
// extra evaluations of the whole sum and is only exact as s goes to zero.
inline HeightGradient finite_difference_gradient(const std::vector<DirectionalWave>& waves, double x, double z,
                                                 double time, double step) {
    HeightGradient g;
    g.height = step02::height(waves, x, z, time);
    g.dh_dx = (step02::height(waves, x + step, z, time) - step02::height(waves, x - step, z, time)) / (2 * step);
    g.dh_dz = (step02::height(waves, x, z + step, time) - step02::height(waves, x, z - step, time)) / (2 * step);
    return g;
}

inline Vec3 tangent(const HeightGradient& g) { return {1, g.dh_dx, 0}; }
inline Vec3 bitangent(const HeightGradient& g) { return {0, g.dh_dz, 1}; }
inline Vec3 normal(const HeightGradient& g) { return normalize({-g.dh_dx, 1, -g.dh_dz}); }

}  // namespace step03
