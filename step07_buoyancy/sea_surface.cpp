#include "step07_buoyancy/sea_surface.hpp"

#include "common/constants.hpp"
#include "step05_fft/gerstner.hpp"

#include <cmath>

namespace step07 {

double GerstnerWave::wavenumber() const { return ocean::kTwoPi / wavelength; }
double GerstnerWave::omega() const { return std::sqrt(ocean::kGravity * wavenumber()); }

namespace {

// Wave w as step05's closed form (gerstner.hpp) with steepness 1, its orbits' radius `amplitude`,
// sampled at `rest`: theta = k d.rest - (omega t - phase).
step05::MapSample sample_wave(const GerstnerWave& w, double amplitude, glm::dvec2 rest, double time) {
    step05::GerstnerWave wave;
    wave.direction_x = w.direction.x;
    wave.direction_z = w.direction.y;
    wave.wavenumber = w.wavenumber();
    wave.amplitude = amplitude;
    wave.steepness = 1;
    return step05::gerstner_sample(wave, rest.x, rest.y, w.omega() * time - w.phase);
}

}  // namespace

SurfaceAt GerstnerSea::at(glm::dvec2 rest) const {
    SurfaceAt s;
    for (const GerstnerWave& w : waves_) {
        const step05::MapSample m = sample_wave(w, w.amplitude, rest, time_);
        // The maps' form: displacement (Dx, h, Dz, dDx/dz), slopes (dh/dx, dh/dz, dDx/dx, dDz/dz).
        s.displacement += glm::dvec3(m.displacement[0], m.displacement[1], m.displacement[2]);
        s.d_dx += glm::dvec3(m.slopes[2], m.slopes[0], m.displacement[3]);
        s.d_dz += glm::dvec3(m.displacement[3], m.slopes[1], m.slopes[3]);
    }
    return s;
}

glm::dvec3 GerstnerSea::displacement_below(glm::dvec2 rest, double depth) const {
    glm::dvec3 d(0.0);
    for (const GerstnerWave& w : waves_) {
        // The orbit at that depth: radius A e^{-k depth}.
        const step05::MapSample m = sample_wave(w, w.amplitude * std::exp(-w.wavenumber() * depth), rest, time_);
        d += glm::dvec3(m.displacement[0], m.displacement[1], m.displacement[2]);
    }
    return d;
}

namespace {

// One cascade read bilinearly and periodically at a rest position.
SurfaceAt sample(const CascadeMaps& m, glm::dvec2 rest) {
    SurfaceAt s;
    // In texels: texel i sits at i tile / n, so no half-texel offset here (map_uv adds it on
    // the GPU, where texel centres are at (i + 0.5) / n).
    const glm::dvec2 t = rest / m.tile * double(m.n);
    const glm::dvec2 cell = glm::floor(t);
    const glm::dvec2 f = t - cell;
    const auto wrap = [&](double v) { return int(v - std::floor(v / m.n) * m.n) % m.n; };
    const int i0 = wrap(cell.x), j0 = wrap(cell.y), i1 = (i0 + 1) % m.n, j1 = (j0 + 1) % m.n;
    const double w[4] = {(1 - f.x) * (1 - f.y), f.x * (1 - f.y), (1 - f.x) * f.y, f.x * f.y};
    const int texels[4] = {j0 * m.n + i0, j0 * m.n + i1, j1 * m.n + i0, j1 * m.n + i1};
    for (int q = 0; q < 4; ++q) {
        const float* d = &m.displacement[std::size_t(texels[q]) * 4];
        const float* sl = &m.slopes[std::size_t(texels[q]) * 4];
        // d/dx of (l Dx, h, l Dz) is (l dDx/dx, dh/dx, l dDz/dx), and dDz/dx = dDx/dz.
        s.displacement += w[q] * glm::dvec3(d[0], d[1], d[2]);
        s.d_dx += w[q] * glm::dvec3(sl[2], sl[0], d[3]);
        s.d_dz += w[q] * glm::dvec3(d[3], sl[1], sl[3]);
    }
    return s;
}

}  // namespace

SurfaceAt MapSea::at(glm::dvec2 rest) const {
    SurfaceAt s;
    for (const CascadeMaps& m : cascades_) {
        const SurfaceAt c = sample(m, rest);
        s.displacement += c.displacement;
        s.d_dx += c.d_dx;
        s.d_dz += c.d_dz;
    }
    return s;
}

glm::dvec3 MapSea::displacement_below(glm::dvec2 rest, double depth) const {
    glm::dvec3 d(0.0);
    for (const CascadeMaps& m : cascades_)
        d += std::exp(-m.wavenumber * depth) * sample(m, rest).displacement;
    return d;
}

}  // namespace step07
