#include "step06_foam_sky/extra_waves.hpp"

#include "step06_foam_sky/texture_units.h"

#include <glm/common.hpp>

#include <cmath>
#include <cstddef>

namespace step06 {

ExtraWaveSample extra_waves_at(const ExtraWaveMaps& maps, glm::dvec2 rest) {
    ExtraWaveSample s;
    if (maps.n < 2) return s;
    const glm::dvec2 q = (rest - maps.first_cell) / maps.cell;
    const double last = double(maps.n - 1);
    if (q.x < 0 || q.y < 0 || q.x >= last || q.y >= last) return s;
    const int i = int(std::floor(q.x)), j = int(std::floor(q.y));
    const double fx = q.x - i, fz = q.y - j;
    const auto texel = [&](const std::vector<float>& map, int di, int dj) {
        const std::size_t c = 4 * (std::size_t(j + dj) * std::size_t(maps.n) + std::size_t(i + di));
        return glm::dvec4(map[c], map[c + 1], map[c + 2], map[c + 3]);
    };
    const auto bilinear = [&](const std::vector<float>& map) {
        const glm::dvec4 bottom = glm::mix(texel(map, 0, 0), texel(map, 1, 0), fx);
        const glm::dvec4 top = glm::mix(texel(map, 0, 1), texel(map, 1, 1), fx);
        return glm::mix(bottom, top, fz);
    };
    s.displacement = bilinear(maps.displacement);
    s.slopes = bilinear(maps.slopes);
    return s;
}

void ExtraWaves::upload(const ExtraWaveMaps& maps) {
    if (maps.n <= 0) {
        n_ = 0;
        return;
    }
    if (maps.n != n_) {
        displacement_ = ocean::make_float_texture_2d(GL_RGBA32F, maps.n, maps.n);
        slopes_ = ocean::make_float_texture_2d(GL_RGBA32F, maps.n, maps.n);
        n_ = maps.n;
    }
    ocean::upload_float_texture_2d(displacement_, GL_RGBA32F, n_, n_, maps.displacement.data());
    ocean::upload_float_texture_2d(slopes_, GL_RGBA32F, n_, n_, maps.slopes.data());
    cell_ = maps.cell;
    first_cell_ = maps.first_cell;
}

void ExtraWaves::bind(const ocean::ShaderProgram& p, glm::dvec2 world_origin) const {
    ocean::bind_texture(UNIT_EXTRA_DISPLACEMENT, GL_TEXTURE_2D, displacement_.id());
    ocean::bind_texture(UNIT_EXTRA_SLOPES, GL_TEXTURE_2D, slopes_.id());
    // From the world origin near the camera, in double, then float: small numbers anywhere.
    p.set("u_extra_first_cell", glm::vec2(first_cell_ - world_origin));
    p.set("u_extra_cell", float(cell_));
}

}  // namespace step06
