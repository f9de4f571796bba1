#include "step07_buoyancy/sea_surface.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step07 {

double GerstnerWave::wavenumber() const { return ocean::kTwoPi / wavelength; }
double GerstnerWave::omega() const { return std::sqrt(ocean::kGravity * wavenumber()); }

SurfaceAt GerstnerSea::at(glm::dvec2 rest) const {
    SurfaceAt s;
    for (const GerstnerWave& w : waves_) {
        const double k = w.wavenumber();
        const glm::dvec2 kv = k * w.direction;
        const double theta = glm::dot(kv, rest) - w.omega() * time_ + w.phase;
        const double c = std::cos(theta), sn = std::sin(theta);
        // (Dx, h, Dz) = (-dx A sin, A cos, -dz A sin); d/dx of theta is kx, of z kz.
        s.displacement += glm::dvec3(-w.direction.x * w.amplitude * sn, w.amplitude * c, -w.direction.y * w.amplitude * sn);
        const glm::dvec3 d_dtheta(-w.direction.x * w.amplitude * c, -w.amplitude * sn, -w.direction.y * w.amplitude * c);
        s.d_dx += kv.x * d_dtheta;
        s.d_dz += kv.y * d_dtheta;
    }
    return s;
}

glm::dvec3 GerstnerSea::displacement_below(glm::dvec2 rest, double depth) const {
    glm::dvec3 d(0.0);
    for (const GerstnerWave& w : waves_) {
        const double theta = glm::dot(w.wavenumber() * w.direction, rest) - w.omega() * time_ + w.phase;
        const double radius = w.amplitude * std::exp(-w.wavenumber() * depth);  // the orbit at that depth
        d += glm::dvec3(-w.direction.x * radius * std::sin(theta), radius * std::cos(theta),
                        -w.direction.y * radius * std::sin(theta));
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
