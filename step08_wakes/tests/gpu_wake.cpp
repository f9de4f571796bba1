// The wake as step06's shaders read it (extra_waves.glsl, from the textures step06::ExtraWaves
// uploads) against step06's extra_waves_at, the CPU reference in double, on a grid of points over
// the wake's grid and past its edges, from a world origin far from it (as the program's, which
// sits near the camera).
#include "step06_foam_sky/extra_waves.hpp"
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step08_wakes/wake_sea.hpp"
#include "tests/gpu/full_screen_draw.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

struct Step08Gpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

TEST_F(Step08Gpu, TheShadersReadTheWakeAsTheCpuDoes) {
    step08::WaveFieldSettings s;
    s.n = 64;
    s.cell = 0.5;
    s.absorbing_width = 4;
    step08::WakeScene scene(s);
    step08::BoatSettings boat;
    scene.place({10000.25, -20000.5}, {1, 0.3});  // far out: the positions go to the GPU from an origin near it
    scene.sail(8, boat, 0.3);
    const step06::ExtraWaveMaps maps = step08::wake_maps(scene.field(), 1.3);
    step06::ExtraWaves waves;
    waves.upload(maps);
    ocean::ShaderProgram* program =
        cache("extra_waves_at", {"common/shaders/fullscreen.vert", "step06_foam_sky/tests/extra_waves_at.frag"}, {});
    ASSERT_NE(program, nullptr);
    const glm::dvec2 origin = glm::floor(scene.boat_position());  // the world origin near the boat
    waves.bind(*program, origin);
    // 160 x 160 points 0.23 m apart (not a divisor of the cell): over the 32 m grid and 2.8 m past it.
    const int size = 160;
    const double step = 0.23;
    const glm::dvec2 first = maps.first_cell - glm::dvec2(3.0);
    program->set("u_first", glm::vec2(first - origin));
    program->set("u_step", float(step));
    double worst = 0, largest = 0;
    int outside = 0;
    for (int which = 0; which < 2; ++which) {
        program->set("u_slopes", which);
        const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*program, size, size, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4);
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                const glm::dvec2 p = first + glm::dvec2(i, j) * step;
                const step06::ExtraWaveSample cpu = step06::extra_waves_at(maps, p);
                const glm::dvec4 want = which == 1 ? cpu.slopes : cpu.displacement;
                const std::size_t texel = 4 * (std::size_t(j) * size + std::size_t(i));
                for (int q = 0; q < 4; ++q) {
                    worst = std::max(worst, std::abs(double(gpu[texel + std::size_t(q)]) - want[q]));
                    largest = std::max(largest, std::abs(want[q]));
                }
                outside += which == 0 && want == glm::dvec4(0.0);
            }
    }
    std::printf("wake as the shaders read it: worst |GPU - CPU| %.2g (values up to %.2f); points outside the grid: %d\n", worst, largest,
                outside);
    EXPECT_GT(largest, 0.05);
    EXPECT_GT(outside, 1000) << "the points must reach past the grid";
    // Float positions from an origin within a metre (a few parts in 1e7 of a cell) move a bilinear
    // weight by about 1e-6: 1e-5 of the largest value. A texel read one over, or the axes swapped,
    // is off by a good part of a wave's height.
    EXPECT_LT(worst, 1e-5 * std::max(largest, 1.0));
}

}  // namespace
