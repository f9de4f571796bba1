// The wake as step06's shaders read it (extra_waves.glsl, from the textures step06::ExtraWaves
// uploads) against step06's extra_waves_at, the CPU reference in double, on a grid of points over
// the wake's grid and past its edges, from a world origin far from it (as the program's, which
// sits near the camera).
#include "step06_foam_sky/extra_waves.hpp"
#include "step06_foam_sky/tests/extra_waves_read.hpp"
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step08_wakes/wake_sea.hpp"
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
    const glm::dvec2 origin = glm::floor(scene.boat_position());  // the world origin near the boat
    // 160 x 160 points 0.23 m apart (not a divisor of the cell): over the 32 m grid and 2.8 m past it.
    const auto gpu = step06_test::read_by_the_shaders(cache, maps, origin, maps.first_cell - glm::dvec2(3.0), 0.23, 160);
    ASSERT_TRUE(gpu);
    double worst = 0, largest = 0;
    int outside = 0;
    for (int which = 0; which < 2; ++which)
        for (int j = 0; j < gpu->size; ++j)
            for (int i = 0; i < gpu->size; ++i) {
                const step06::ExtraWaveSample cpu = step06::extra_waves_at(maps, gpu->point(i, j));
                const glm::dvec4 want = which == 1 ? cpu.slopes : cpu.displacement;
                const glm::dvec4 shader = gpu->at(i, j, which == 1);
                for (int q = 0; q < 4; ++q) {
                    worst = std::max(worst, std::abs(shader[q] - want[q]));
                    largest = std::max(largest, std::abs(want[q]));
                }
                outside += which == 0 && want == glm::dvec4(0.0);
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
