// The program's boat and stones, as a learner would check them: the boat goes where it is steered,
// its wake lies behind it (none ahead), the grid keeps up with it, and a stone makes rings around
// where it fell, high enough for the default camera to show.
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_scene.hpp"

#include "common/constants.hpp"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace {

step08::WaveFieldSettings small_field() {
    step08::WaveFieldSettings s;
    s.n = 64;
    s.cell = 1;
    s.absorbing_width = 8;
    return s;
}

// The mean of eta^2 over the cells within `radius` of `at`.
double wave_power_near(const step08::WaveField& f, glm::dvec2 at, double radius) {
    double sum = 0;
    int count = 0;
    for (int j = 0; j < f.n(); ++j)
        for (int i = 0; i < f.n(); ++i)
            if (glm::length(f.cell_centre(i, j) - at) < radius) {
                sum += f.heights()[std::size_t(j * f.n() + i)] * f.heights()[std::size_t(j * f.n() + i)];
                ++count;
            }
    return count > 0 ? sum / count : 0;
}

TEST(Step08WakeScene, TheBoatSailsWhereItIsSteeredAndTheGridFollows) {
    step08::WakeScene scene(small_field());
    step08::BoatSettings boat;  // 4 m/s, 20 degrees a second with the rudder hard over
    scene.sail(5, boat, 0);
    EXPECT_NEAR(scene.boat_position().x, 20, 1e-9);
    EXPECT_NEAR(scene.boat_position().y, 0, 1e-9);
    scene.sail(2, boat, 1);  // hard to starboard: 40 degrees, from +x towards +z
    EXPECT_NEAR(std::atan2(scene.boat_heading().y, scene.boat_heading().x) * 180 / ocean::kPi, 40, 1e-9);
    // The grid's centre within a cell of a quarter side behind the boat.
    const step08::WaveField& f = scene.field();
    const glm::dvec2 centre = 0.5 * (f.cell_centre(0, 0) + f.cell_centre(f.n() - 1, f.n() - 1));
    const glm::dvec2 expected = scene.boat_position() - 0.25 * f.side() * scene.boat_heading();
    EXPECT_LT(glm::length(centre - expected), 1.5 * f.settings().cell);
}

// The waves are behind the boat: a steady wake cannot run ahead of its source (deep water's
// waves that keep pace with it are the transverse ones, behind), so ahead of the bow the water
// is nearly still; behind, the wake.
TEST(Step08WakeScene, TheWakeIsBehindTheBoatNotAhead) {
    step08::WakeScene scene(small_field());
    step08::BoatSettings boat;
    boat.speed = 3;
    scene.sail(30, boat, 0);
    const glm::dvec2 at = scene.boat_position(), ahead = scene.boat_heading();
    const double in_front = wave_power_near(scene.field(), at + 10.0 * ahead, 4);
    const double behind = wave_power_near(scene.field(), at - 12.0 * ahead, 4);
    std::cout << "rms ahead " << std::sqrt(in_front) << " m, behind " << std::sqrt(behind) << " m" << std::endl;
    EXPECT_GT(behind, 0);
    EXPECT_LT(in_front, 0.01 * behind);
}

// A stone on calm water: rings around it, the same height in every direction.
TEST(Step08WakeScene, AStoneMakesRingsAroundWhereItFell) {
    step08::WaveFieldSettings s;
    s.n = 128;
    s.cell = 0.1;
    s.absorbing_width = 2;
    step08::WakeScene scene(s);
    step08::BoatSettings still;  // a boat at rest that does not touch the water: only the stone
    still.speed = 0;
    still.draft = 0;
    scene.sail(0.1, still, 0);  // the grid takes its place around the boat
    const glm::dvec2 stone = scene.field().cell_centre(64, 64);
    scene.drop_stone(stone);
    scene.sail(2, still, 0);
    const step08::WaveField& f = scene.field();
    double north = 0, east = 0, at_3m = 0;
    for (double r = 2; r < 4; r += 0.05) {
        north = std::max(north, std::abs(f.height_at(stone + glm::dvec2(0, r))));
        east = std::max(east, std::abs(f.height_at(stone + glm::dvec2(r, 0))));
    }
    at_3m = std::max(north, east);
    EXPECT_GT(at_3m, 1e-4) << "the rings reached 2 to 4 m in 2 s";
    EXPECT_NEAR(north / east, 1, 0.02) << "round rings";
}

// The default stone (a click's) on the program's default grid (128 cells of 0.5 m) shows from the
// program's default camera: 45 m from the boat, 50 degrees of view over 720 rows, where one pixel
// spans 2 x 45 tan 25 / 720 = 5.8 cm. Screenshots of step06's breeze 1 s after a click
// (how_we_know.md) showed a splash of 3 pixels from crest to trough (a 1 m^4/s stone) hardly, and
// one of 6 plainly, foaming: so, a second on, the heap where it fell and the trough around it span
// 4 pixels, and within that second the splash's own Jacobian (at the sea's default choppiness,
// 1.3) falls below step06's foam threshold, 0.64, so that it foams on any sea. Two seconds on, the
// ring beyond 1.5 m spans 2 pixels; from then on, 1.5 m and more from the splash, the rings are
// linear waves, their slopes below 0.44, the k A at which a Stokes wave breaks.
TEST(Step08WakeScene, TheDefaultStonesRingsShowFromTheDefaultCamera) {
    step08::WakeScene scene(step08::WaveFieldSettings{});
    step08::BoatSettings still;  // a boat at rest that does not touch the water: only the stone
    still.speed = 0;
    still.draft = 0;
    scene.sail(0.1, still, 0);
    const glm::dvec2 stone = scene.field().cell_centre(64, 64);
    scene.drop_stone(stone);
    const double pixel = 2 * 45 * std::tan(25 * ocean::kPi / 180) / 720;
    const step08::WaveField& f = scene.field();
    const int n = f.n();
    const auto height = [&](int i, int j) { return f.heights()[std::size_t(j * n + i)]; };
    const auto distance = [&](int i, int j) { return glm::length(f.cell_centre(i, j) - stone); };
    // The span (highest minus lowest) of the cells `from` to `to` metres from the stone.
    const auto span = [&](double from, double to) {
        double high = 0, low = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (distance(i, j) >= from && distance(i, j) <= to)
                    high = std::max(high, height(i, j)), low = std::min(low, height(i, j));
        return high - low;
    };
    double lowest_jacobian = 1, steepest_ring = 0;
    for (int frame = 1; frame <= 180; ++frame) {  // 3 s
        scene.sail(1.0 / 60, still, 0);
        if (frame <= 60) {
            const step06::ExtraWaveMaps maps = step08::wake_maps(f, 1.3);
            for (std::size_t c = 0; c < maps.slopes.size() / 4; ++c) {
                const double dxx = maps.slopes[4 * c + 2], dzz = maps.slopes[4 * c + 3], dxz = maps.displacement[4 * c + 3];
                lowest_jacobian = std::min(lowest_jacobian, (1 + dxx) * (1 + dzz) - dxz * dxz);
            }
        }
        if (frame == 60) {
            std::cout << "1 s after the stone, within 3 m: " << span(0, 3) << " m crest to trough (a pixel: " << pixel
                      << " m); the lowest Jacobian so far " << lowest_jacobian << std::endl;
            EXPECT_GT(span(0, 3), 4 * pixel) << "the splash's heap and trough, 1 s on";
            EXPECT_LT(lowest_jacobian, 0.64) << "the splash foams within a second";
        }
        if (frame == 120) {
            std::cout << "2 s after the stone, 1.5 to 4 m out: " << span(1.5, 4) << " m crest to trough" << std::endl;
            EXPECT_GT(span(1.5, 4), 2 * pixel) << "the ring, 2 s on";
        }
        if (frame >= 60)
            for (int j = 1; j + 1 < n; ++j)
                for (int i = 1; i + 1 < n; ++i)
                    if (distance(i, j) >= 1.5)
                        steepest_ring = std::max(steepest_ring, std::hypot(height(i + 1, j) - height(i - 1, j),
                                                                           height(i, j + 1) - height(i, j - 1)) /
                                                                    (2 * f.settings().cell));
    }
    std::cout << "the rings' steepest slope 1.5 m out or more, 1 to 3 s on: " << steepest_ring << std::endl;
    EXPECT_LT(steepest_ring, 0.44) << "the rings steeper than a wave can stand";
}

}  // namespace
