#include "step08_wakes/wake_sea.hpp"

#include <cmath>

namespace step08 {

WakeSample wake_at(const step06::ExtraWaveMaps& wake, glm::dvec2 rest) {
    WakeSample s;
    if (wake.n < 2) return s;
    const glm::dvec2 q = (rest - wake.first_cell) / wake.cell;
    const double last = double(wake.n - 1);
    if (q.x < 0 || q.y < 0 || q.x >= last || q.y >= last) return s;
    const int i = int(std::floor(q.x)), j = int(std::floor(q.y));
    const double fx = q.x - i, fz = q.y - j;
    const auto texel = [&](const std::vector<float>& map, int di, int dj) {
        const std::size_t c = 4 * (std::size_t(j + dj) * std::size_t(wake.n) + std::size_t(i + di));
        return glm::dvec4(map[c], map[c + 1], map[c + 2], map[c + 3]);
    };
    const auto bilinear = [&](const std::vector<float>& map) {
        const glm::dvec4 bottom = glm::mix(texel(map, 0, 0), texel(map, 1, 0), fx);
        const glm::dvec4 top = glm::mix(texel(map, 0, 1), texel(map, 1, 1), fx);
        return glm::mix(bottom, top, fz);
    };
    s.displacement = bilinear(wake.displacement);
    s.slopes = bilinear(wake.slopes);
    return s;
}

step07::SurfaceAt SeaWithWake::at(glm::dvec2 rest) const {
    step07::SurfaceAt s = sea_.at(rest);
    const WakeSample w = wake_at(wake_, rest);
    s.displacement += glm::dvec3(w.displacement);
    // d/dx of (l Dx, h, l Dz) is (l dDx/dx, dh/dx, l dDz/dx), and dDz/dx = dDx/dz (a gradient's
    // mixed derivatives); d/dz is (l dDx/dz, dh/dz, l dDz/dz).
    s.d_dx += glm::dvec3(w.slopes.z, w.slopes.x, w.displacement.w);
    s.d_dz += glm::dvec3(w.displacement.w, w.slopes.y, w.slopes.w);
    return s;
}

glm::dvec3 SeaWithWake::displacement_below(glm::dvec2 rest, double depth) const {
    return sea_.displacement_below(rest, depth) + glm::dvec3(wake_at(wake_, rest).displacement);
}

}  // namespace step08
