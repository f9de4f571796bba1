// Chapter 3 on the CPU, in double precision: sharper waves, fractional Brownian motion, domain
// warping, and several sums layered (cascades). The GPU (fbm.glsl) is tested against this.
//
// One cascade is a sum of N waves. Wave i has
//   amplitude a_i = a_0 gain^i,  angular wavenumber w_i = w_0 lacunarity^i   (fBm: 0.82, 1.18)
//   a direction d_i drawn from a seeded generator, and phase rate phi_i = speed_scale sqrt(g w_i)
//   (deep water: short waves are slower), and a shape W: sin, exp(sin - 1) (sharp crests), or GPU
//   Gems' ((1 + sin) / 2)^3 (sharp crests, troughs flatter still).
// Wave i is a_i W(w_i d_i.q - t phi_i): its crests travel along +d_i (the notes' + t phi would send
// them along -d_i). exp(sin - 1) is not centred: its mean over a period is e^-1 I0(1) = 0.4658, so
// the step subtracts it and the water's mean level stays at y = 0 (without it, the step's two
// cascades of 20 waves from a_0 = 1.2 m float the sea about 4 m up, 3.0 m and 1.1 m; one cascade of
// CascadeSettings' default 24 waves from a_0 = 1 m, 2.6 m).
// Domain warping: each wave is evaluated at a point q_i that the waves before it have pushed
// downhill, q_{i+1} = q_i - s a_i grad f_i(q_i), with a dimensionless strength s. The push is
// weighted by the wave's amplitude (as Acerola's "drag" is): without it, the fBm's short waves,
// whose slopes barely shrink from one to the next, would fold the domain into noise.
// The normal stays exact: the chain rule carries J = dq_i/dp through the loop, and
//   grad h(p) = sum_i J_i^T grad f_i(q_i),   J_{i+1} = (I - s a_i^2 w_i^2 W''(theta_i) d_i d_i^T) J_i.
#pragma once

#include "step02_sine3d/waves.hpp"
#include "step03_lighting/normals.hpp"
#include "common/random.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace step04 {

using ocean::kGravity;
using ocean::kTwoPi;

enum class Shape { Sine = 0, ExpSine = 1, PowerSine = 2 };

// W(theta) and its first two derivatives.
struct ShapeValue {
    double value, first, second;
};

// The mean of exp(sin(theta) - 1) over a period: e^-1 I0(1), with I0 the modified Bessel function.
constexpr double kExpSineMean = 0.46575960759364043;

// The sine is scaled to the exp-sine's crest-to-trough height, 1 - e^-2 (its own is 2), so that
// `shape` compares two seas of the same height, not a sine sea 2.3 times higher.
constexpr double kSineScale = 0.43233235838169365;  // (1 - e^-2) / 2

// GPU Gems 1's sharpened sine (Finch 2004, chapter 1), ((1 + sin theta) / 2)^k with k = 3: 1 at the
// crest, 0 in the trough, scaled to the exp-sine's crest-to-trough height 1 - e^-2 and its mean
// removed; (W, W', W''). Exercise 4 (./ocean exercise step04_fbm 4) derives it: fbm.glsl's
// power_sine_shape.
inline ShapeValue power_sine_shape(double theta) {
    const double s = std::sin(theta), c = std::cos(theta), u = 0.5 * (1 + s), scale = 1 - std::exp(-2.0);
    // u^3 = (1 + 3 s + 3 s^2 + s^3) / 8, whose odd powers of sin average 0 and sin^2 1/2: mean 5/16.
    return {scale * (u * u * u - 5.0 / 16), scale * 1.5 * u * u * c, scale * 1.5 * (u * c * c - u * u * s)};
}

inline ShapeValue wave_shape(Shape shape, double theta) {
    const double s = std::sin(theta), c = std::cos(theta);
    if (shape == Shape::Sine) return {kSineScale * s, kSineScale * c, -kSineScale * s};
    if (shape == Shape::PowerSine) return power_sine_shape(theta);
    const double e = std::exp(s - 1.0);  // in [e^-2, 1]: a crest of 1, flat troughs
    return {e - kExpSineMean, e * c, e * (c * c - s)};
}

struct FbmWave {
    double dx, dz;       // unit direction
    double wavenumber;   // w, radians per metre
    double amplitude;    // a, metres
    double phase_rate;   // phi, radians per second
};

constexpr int kMaxCascades = 4;            // MAX_CASCADES in fbm.glsl
constexpr int kMaxWavesPerCascade = 64;    // MAX_WAVES_PER_CASCADE

struct CascadeSettings {
    int wave_count = 24;
    double base_wavelength = 40;  // metres, of wave 0
    double base_amplitude = 1;    // metres, a_0
    double gain = 0.82;           // amplitude ratio between neighbouring waves
    double lacunarity = 1.18;     // frequency ratio between neighbouring waves
    double speed_scale = 1;       // a factor on the phase rate: 1 = deep water
    std::uint64_t seed = 1;
};

inline std::vector<FbmWave> fbm_waves(const CascadeSettings& s) {
    std::vector<FbmWave> waves;
    std::uint64_t state = s.seed;
    double amplitude = s.base_amplitude, wavenumber = kTwoPi / s.base_wavelength;
    for (int i = 0; i < s.wave_count; ++i) {
        const double angle = kTwoPi * ocean::uniform01(state);  // the same sea on every machine
        waves.push_back({std::cos(angle), std::sin(angle), wavenumber, amplitude,
                         s.speed_scale * std::sqrt(kGravity * wavenumber)});
        amplitude *= s.gain;
        wavenumber *= s.lacunarity;
    }
    return waves;
}

// Height and exact gradient of one warped cascade at p = (x, z).
inline step03::HeightGradient cascade_height_gradient(const std::vector<FbmWave>& waves, Shape shape,
                                                      double warp, double x, double z, double time) {
    double qx = x, qz = z;                        // the warped point
    double j00 = 1, j01 = 0, j10 = 0, j11 = 1;    // J = dq/dp, row-major: [dqx/dx dqx/dz; dqz/dx dqz/dz]
    step03::HeightGradient g;
    for (const FbmWave& wave : waves) {
        const double theta = (wave.dx * qx + wave.dz * qz) * wave.wavenumber + step01::phase_at(wave.phase_rate, time);
        const ShapeValue v = wave_shape(shape, theta);
        g.height += wave.amplitude * v.value;
        const double slope = wave.amplitude * wave.wavenumber * v.first;  // df/d(along d)
        const double fx = slope * wave.dx, fz = slope * wave.dz;          // grad_q f
        g.dh_dx += j00 * fx + j10 * fz;                                   // J^T grad_q f
        g.dh_dz += j01 * fx + j11 * fz;
        // J <- (I - kappa d d^T) J with kappa = beta a^2 w^2 W''
        const double k = warp * wave.amplitude * wave.amplitude * wave.wavenumber * wave.wavenumber * v.second;
        const double r0 = wave.dx * j00 + wave.dz * j10, r1 = wave.dx * j01 + wave.dz * j11;  // d^T J
        j00 -= k * wave.dx * r0;
        j01 -= k * wave.dx * r1;
        j10 -= k * wave.dz * r0;
        j11 -= k * wave.dz * r1;
        qx -= warp * wave.amplitude * fx;
        qz -= warp * wave.amplitude * fz;
    }
    return g;
}

struct Cascade {
    std::vector<FbmWave> waves;
};

// Several independent sums with different base wavelengths, added: their repeats do not line
// up, which hides the periodicity of any one of them.
inline step03::HeightGradient height_gradient(const std::vector<Cascade>& cascades, Shape shape, double warp,
                                              double x, double z, double time) {
    step03::HeightGradient total;
    for (const auto& cascade : cascades) {
        const auto g = cascade_height_gradient(cascade.waves, shape, warp, x, z, time);
        total.height += g.height;
        total.dh_dx += g.dh_dx;
        total.dh_dz += g.dh_dz;
    }
    return total;
}

// Cascade c: base wavelength and amplitude scaled by ratio^c, its own seed.
inline std::vector<Cascade> make_cascades(const CascadeSettings& first, int count, double ratio) {
    std::vector<Cascade> cascades;
    for (int c = 0; c < count; ++c) {
        CascadeSettings s = first;
        s.base_wavelength = first.base_wavelength * std::pow(ratio, c);
        s.base_amplitude = first.base_amplitude * std::pow(ratio, c);
        s.seed = first.seed + 7919u * std::uint64_t(c);
        cascades.push_back({fbm_waves(s)});
    }
    return cascades;
}

}  // namespace step04
