// Extra waves as the shaders read them (extra_waves.glsl, through tests/extra_waves_at.frag, from
// the textures ExtraWaves uploads): at size x size points `step` metres apart from `first` (world
// x, z), the world origin at `origin`, as a program's sits near its camera. A test holds each
// point to what it expects there (the CPU reference, a closed form).
#pragma once

#include "step06_foam_sky/extra_waves.hpp"
#include "tests/gpu/full_screen_draw.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <optional>
#include <vector>

namespace step06_test {

struct ShaderRead {
    int size = 0;
    glm::dvec2 first{0.0};
    double step = 0;
    std::vector<float> displacement, slopes;  // 4 floats a point, rows of `size` points

    glm::dvec2 point(int i, int j) const { return first + glm::dvec2(i, j) * step; }
    // Point (i, j)'s displacement (slopes = false) or slopes.
    glm::dvec4 at(int i, int j, bool slopes_map) const {
        const std::vector<float>& map = slopes_map ? slopes : displacement;
        const std::size_t texel = 4 * (std::size_t(j) * std::size_t(size) + std::size_t(i));
        return {map[texel], map[texel + 1], map[texel + 2], map[texel + 3]};
    }
};

// Nothing when the evaluation shader does not build.
inline std::optional<ShaderRead> read_by_the_shaders(ocean_test::ProgramCache& cache, const step06::ExtraWaveMaps& maps,
                                                     glm::dvec2 origin, glm::dvec2 first, double step, int size) {
    ocean::ShaderProgram* program = cache(
        "extra_waves_at", {"common/shaders/fullscreen.vert", "step06_foam_sky/tests/extra_waves_at.frag"}, {});
    if (program == nullptr) return std::nullopt;
    step06::ExtraWaves waves;
    waves.upload(maps);
    waves.bind(*program, origin);
    program->set("u_first", glm::vec2(first - origin));
    program->set("u_step", float(step));
    ShaderRead read{size, first, step, {}, {}};
    for (int which = 0; which < 2; ++which) {
        program->set("u_slopes", which);
        (which == 1 ? read.slopes : read.displacement) =
            ocean_test::draw_full_screen<float>(*program, size, size, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4);
    }
    return read;
}

}  // namespace step06_test
