// The wake as step06's sea draws it (wake_maps.hpp) and as step07's bodies feel it (wake_sea.hpp),
// held to something outside the code: one wave in the field is step05's Gerstner wave of the same
// height (step07's GerstnerSea, a closed form), a choppiness scales only the sideways motion, and
// the boat's wake folds (its Jacobian falls) on its crests, where foam belongs.
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step08_wakes/wake_sea.hpp"

#include "common/constants.hpp"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

// A field of 64 cells of 0.5 m holding one wave h = A cos(k.x + phase), k a mode of the grid.
struct OneWave {
    step08::WaveField field;
    step07::GerstnerWave wave;
};
OneWave one_wave() {
    step08::WaveFieldSettings s;
    s.n = 64;
    s.cell = 0.5;
    s.absorbing_width = 0;
    OneWave w{step08::WaveField(s), {}};
    const glm::dvec2 k = w.field.wavenumber(3, 2);  // 3 and 2 wavelengths across the 32 m grid
    w.wave.amplitude = 0.2;
    w.wave.wavelength = ocean::kTwoPi / glm::length(k);
    w.wave.direction = glm::normalize(k);
    w.wave.phase = 0.7;
    for (int j = 0; j < s.n; ++j)
        for (int i = 0; i < s.n; ++i)
            w.field.heights()[std::size_t(j * s.n + i)] =
                w.wave.amplitude * std::cos(glm::dot(k, w.field.cell_centre(i, j)) + w.wave.phase);
    return w;
}

// The field's maps, read at each cell centre through SeaWithWake on still water, are the Gerstner
// wave's displacement and derivatives (step07's GerstnerSea at t = 0, crests pulled together as
// step05 draws them), to float's rounding: 1e-6 m on heights of 0.2 m, slopes of 0.1.
TEST(Step08WakeMaps, OneWaveIsStep05sGerstnerWave) {
    const OneWave w = one_wave();
    const step06::LocalWaveMaps maps = step08::wake_maps(w.field, 1.0);
    const step07::FlatSea still;
    const step08::SeaWithWake sea(still, maps);
    const step07::GerstnerSea gerstner({w.wave}, 0.0);
    double worst = 0;
    for (int j = 0; j < 63; ++j)
        for (int i = 0; i < 63; ++i) {
            const glm::dvec2 at = w.field.cell_centre(i, j);
            const step07::SurfaceAt got = sea.at(at), want = gerstner.at(at);
            for (int a = 0; a < 3; ++a) {
                worst = std::max(worst, std::abs(got.displacement[a] - want.displacement[a]));
                worst = std::max(worst, std::abs(got.d_dx[a] - want.d_dx[a]));
                worst = std::max(worst, std::abs(got.d_dz[a] - want.d_dz[a]));
            }
        }
    std::printf("largest difference from the Gerstner wave: %.2e\n", worst);
    EXPECT_LT(worst, 1e-6);
}

// Choppiness pulls the crests together: it scales the sideways motion and its derivatives, never
// the heights or their slopes.
TEST(Step08WakeMaps, ChoppinessScalesOnlyTheSidewaysMotion) {
    const OneWave w = one_wave();
    const step06::LocalWaveMaps full = step08::wake_maps(w.field, 1.0), half = step08::wake_maps(w.field, 0.5);
    for (std::size_t c = 0; c < full.displacement.size(); c += 4) {
        EXPECT_NEAR(half.displacement[c + 1], full.displacement[c + 1], 1e-7);  // h
        EXPECT_NEAR(half.slopes[c], full.slopes[c], 1e-7);                      // dh/dx
        EXPECT_NEAR(half.slopes[c + 1], full.slopes[c + 1], 1e-7);              // dh/dz
        for (std::size_t q : {c, c + 2, c + 3}) EXPECT_NEAR(half.displacement[q], 0.5 * full.displacement[q], 1e-7);
        for (std::size_t q : {c + 2, c + 3}) EXPECT_NEAR(half.slopes[q], 0.5 * full.slopes[q], 1e-7);
    }
}

// A user's check of the boat's wake: where the wake's surface folds most (the lowest Jacobian of
// its choppy displacement, where step06 makes foam) it stands high: the 1 % of cells with the
// lowest J are on crests, their mean height well above the wake's rms height.
TEST(Step08WakeMaps, TheWakeFoldsOnItsCrests) {
    step08::WaveFieldSettings s;
    s.n = 128;
    s.cell = 0.5;
    s.absorbing_width = 8;
    step08::WakeScene scene(s);
    step08::BoatSettings boat;
    boat.draft = 0.8;
    scene.sail(20, boat, 0);
    const step06::LocalWaveMaps maps = step08::wake_maps(scene.field(), 1.0);
    const std::size_t cells = maps.displacement.size() / 4;
    std::vector<std::pair<double, double>> jacobian_height(cells);
    double rms = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        const double dxx = maps.slopes[4 * c + 2], dzz = maps.slopes[4 * c + 3], dxz = maps.displacement[4 * c + 3];
        const double h = maps.displacement[4 * c + 1];
        jacobian_height[c] = {(1 + dxx) * (1 + dzz) - dxz * dxz, h};
        rms += h * h;
    }
    rms = std::sqrt(rms / double(cells));
    std::sort(jacobian_height.begin(), jacobian_height.end());
    const std::size_t fold = cells / 100;
    double mean = 0;
    for (std::size_t c = 0; c < fold; ++c) mean += jacobian_height[c].second / double(fold);
    std::printf("lowest Jacobian %.3f; the 1 %% lowest: mean height %.3f m against the wake's rms %.3f m\n",
                jacobian_height[0].first, mean, rms);
    EXPECT_LT(jacobian_height[0].first, 1.0);
    EXPECT_GT(mean, 1.5 * rms);
}

// Outside the grid the wake adds nothing; inside, exactly what the maps hold at a cell centre.
TEST(Step08WakeMaps, NothingOutsideTheGrid) {
    const OneWave w = one_wave();
    const step06::LocalWaveMaps maps = step08::wake_maps(w.field, 1.0);
    const double side = w.field.side();
    for (glm::dvec2 outside : {glm::dvec2(-side, 0), glm::dvec2(0, side), glm::dvec2(2 * side, -2 * side)})
        EXPECT_EQ(step08::wake_at(maps, outside).displacement, glm::dvec4(0.0));
    const step08::WakeSample at = step08::wake_at(maps, w.field.cell_centre(10, 20));
    EXPECT_DOUBLE_EQ(at.displacement.y, double(maps.displacement[4 * (20 * 64 + 10) + 1]));
}

}  // namespace
