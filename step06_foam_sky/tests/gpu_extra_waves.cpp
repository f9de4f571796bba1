// Extra waves (extra_waves.hpp) made from a closed form, a plane wave on a 64 x 64 grid of 0.5 m
// cells 10 km from the origin: extra_waves_at, the CPU reference in double, against the closed
// form within the bilinear read's bound; the shaders' read (extra_waves.glsl, from the textures
// ExtraWaves uploads, the world origin near the grid) against extra_waves_at; both zero past the
// grid's edges. And the sea compiles the sum in only when it is given some.
#include "step06_foam_sky/extra_waves.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/tests/extra_waves_read.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

struct Step06ExtraWaves : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

// h = a cos(k.x + phase) with step05's choppy displacement D = -(k/|k|) a sin(k.x + phase) (the
// crests pulled together for l > 0), as step05's two maps hold it at x (world x, z).
struct PlaneWave {
    double a = 0.3;  // metres (k a = 0.24)
    // 8 m long, 30 degrees off x: both axes of the grid matter (fx and fz swapped would show)
    glm::dvec2 k = 2 * 3.14159265358979323846 / 8.0 * glm::dvec2(0.866025403784, 0.5);
    double phase = 0.7;  // rad
    double l = 1.0;      // choppiness

    step06::ExtraWaveSample at(glm::dvec2 x) const {
        const double theta = glm::dot(k, x) + phase, c = std::cos(theta), s = std::sin(theta);
        const double kk = glm::length(k);
        step06::ExtraWaveSample w;
        w.displacement = {-l * a * k.x / kk * s, a * c, -l * a * k.y / kk * s, -l * a * k.x * k.y / kk * c};
        w.slopes = {-a * k.x * s, -a * k.y * s, -l * a * k.x * k.x / kk * c, -l * a * k.y * k.y / kk * c};
        return w;
    }
    // Each term's amplitude: the closed form's factors in front of the sine or cosine.
    step06::ExtraWaveSample amplitudes() const {
        const double kk = glm::length(k), x = std::abs(k.x), z = std::abs(k.y);
        return {{l * a * x / kk, a, l * a * z / kk, l * a * x * z / kk},
                {a * x, a * z, l * a * x * x / kk, l * a * z * z / kk}};
    }
};

step06::ExtraWaveMaps maps_of(const PlaneWave& wave, int n, double cell, glm::dvec2 first_cell) {
    step06::ExtraWaveMaps maps;
    maps.n = n;
    maps.cell = cell;
    maps.first_cell = first_cell;
    maps.displacement.resize(std::size_t(n * n * 4));
    maps.slopes.resize(std::size_t(n * n * 4));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const step06::ExtraWaveSample w = wave.at(first_cell + glm::dvec2(i, j) * cell);
            for (int q = 0; q < 4; ++q) {
                const std::size_t c = 4 * (std::size_t(j) * std::size_t(n) + std::size_t(i)) + std::size_t(q);
                maps.displacement[c] = float(w.displacement[q]);
                maps.slopes[c] = float(w.slopes[q]);
            }
        }
    return maps;
}

TEST_F(Step06ExtraWaves, ThePlaneWaveIsReadAsItsClosedFormByTheCpuAndTheShaders) {
    const PlaneWave wave;
    const int n = 64;
    const double cell = 0.5;
    const step06::ExtraWaveMaps maps = maps_of(wave, n, cell, {10000.25, 5000.75});  // far out
    // The world origin near the grid, as a program's sits near its camera.
    const glm::dvec2 origin = glm::floor(maps.first_cell + 0.5 * cell * (n - 1));
    // 160 x 160 points 0.23 m apart (not a divisor of the cell), from 2.9 m before the first cell's
    // centre to 2.2 m past the last: no point within 0.2 cells of an edge, where a float position
    // and a double one might fall on either side of it.
    const int size = 160;
    const double step = 0.23;
    const glm::dvec2 first = maps.first_cell - glm::dvec2(2.9);
    const auto gpu = step06_test::read_by_the_shaders(cache, maps, origin, first, step, size);
    ASSERT_TRUE(gpu);

    // Bilinear interpolation of f misses it by at most cell^2/8 (|f_xx| + |f_zz|): for each term
    // A cos or A sin of k.x, A (|k| cell)^2 / 8; the maps' floats add 1e-7 A.
    const step06::ExtraWaveSample amplitude = wave.amplitudes();
    const double bilinear = std::pow(glm::length(wave.k) * cell, 2) / 8;
    double worst_closed = 0;  // of |CPU - closed form| / bound
    double worst_gpu = 0, largest = 0;
    int inside = 0, outside = 0, outside_not_zero = 0;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const glm::dvec2 p = gpu->point(i, j);
            // Inside the grid or not, decided here, not by the code under test.
            const glm::dvec2 q = (p - maps.first_cell) / cell;
            const bool in_grid = q.x >= 0 && q.y >= 0 && q.x < n - 1 && q.y < n - 1;
            const step06::ExtraWaveSample cpu = step06::extra_waves_at(maps, p);
            const step06::ExtraWaveSample closed = wave.at(p);
            for (int which = 0; which < 2; ++which) {
                const glm::dvec4 want = which == 1 ? cpu.slopes : cpu.displacement;
                const glm::dvec4 form = which == 1 ? closed.slopes : closed.displacement;
                const glm::dvec4 amp = which == 1 ? amplitude.slopes : amplitude.displacement;
                const glm::dvec4 shader = gpu->at(i, j, which == 1);
                for (int c = 0; c < 4; ++c) {
                    const double read = shader[c];
                    worst_gpu = std::max(worst_gpu, std::abs(read - want[c]));
                    largest = std::max(largest, std::abs(want[c]));
                    if (in_grid)
                        worst_closed = std::max(worst_closed,
                                                std::abs(want[c] - form[c]) / (amp[c] * (bilinear + 1e-7)));
                    else
                        outside_not_zero += want[c] != 0.0 || read != 0.0;
                }
            }
            (in_grid ? inside : outside) += 1;
        }
    std::printf("plane wave on extra waves' grid: |CPU - closed form| up to %.2f of the bilinear bound "
                "(a (k cell)^2/8 = %.2g m); |GPU - CPU| %.2g (values up to %.2f); %d points inside, %d "
                "outside, %d values not zero outside\n",
                worst_closed, wave.a * bilinear, worst_gpu, largest, inside, outside, outside_not_zero);
    EXPECT_GT(inside, 10000);
    EXPECT_GT(outside, 3000) << "the points must reach past the grid";
    // The CPU reference is the closed form, to within what bilinear interpolation can do.
    EXPECT_LE(worst_closed, 1.0);
    // Float positions from an origin within 20 m of every point (a few parts in 1e6 of a cell) move
    // a bilinear weight by a few 1e-6: 1e-5 of the largest value. A texel read one over, or the axes
    // swapped, is off by a good part of a wave's height.
    EXPECT_GT(largest, 0.25);
    EXPECT_LT(worst_gpu, 1e-5 * largest);
    // Nothing past the grid's edges, on the CPU and in the shader.
    EXPECT_EQ(outside_not_zero, 0);
}

TEST_F(Step06ExtraWaves, TheSeaCompilesTheSumInOnlyWhenGivenSome) {
    step06::Sea sea;
    const auto defines = [&] { return sea.shader_defines(); };
    EXPECT_EQ(defines(), std::vector<std::string>{"EXTRA_WAVES 0"});
    step06::ExtraWaves waves;  // none uploaded yet
    sea.add_extra_waves(&waves);
    EXPECT_EQ(defines(), std::vector<std::string>{"EXTRA_WAVES 0"});
    waves.upload(maps_of(PlaneWave{}, 4, 0.5, {0.0, 0.0}));
    EXPECT_EQ(defines(), std::vector<std::string>{"EXTRA_WAVES 1"});
    waves.upload(step06::ExtraWaveMaps{});  // taken away again
    EXPECT_EQ(defines(), std::vector<std::string>{"EXTRA_WAVES 0"});
    sea.add_extra_waves(nullptr);
    EXPECT_EQ(defines(), std::vector<std::string>{"EXTRA_WAVES 0"});
}

}  // namespace
