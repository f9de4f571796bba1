// The wake as step06's sea draws it (wake_maps.hpp) and as step07's bodies feel it (wake_sea.hpp),
// held to something outside the code: one wave in the field is step05's Gerstner wave of the same
// height (step07's GerstnerSea, a closed form), a choppiness scales only the sideways motion, and
// the boat's wake folds (its Jacobian falls) on its crests, where foam belongs.
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step08_wakes/wake_sea.hpp"

#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/body_params.hpp"

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
    const step06::ExtraWaveMaps maps = step08::wake_maps(w.field, 1.0);
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
    const step06::ExtraWaveMaps full = step08::wake_maps(w.field, 1.0), half = step08::wake_maps(w.field, 0.5);
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
    const step06::ExtraWaveMaps maps = step08::wake_maps(scene.field(), 1.0);
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
    const step06::ExtraWaveMaps maps = step08::wake_maps(w.field, 1.0);
    const double side = w.field.side();
    for (glm::dvec2 outside : {glm::dvec2(-side, 0), glm::dvec2(0, side), glm::dvec2(2 * side, -2 * side)})
        EXPECT_EQ(step06::extra_waves_at(maps, outside).displacement, glm::dvec4(0.0));
    const step06::ExtraWaveSample at = step06::extra_waves_at(maps, w.field.cell_centre(10, 20));
    EXPECT_DOUBLE_EQ(at.displacement.y, double(maps.displacement[4 * (20 * 64 + 10) + 1]));
}

}  // namespace

// The program's coupling, as a learner would check it: the hull's dent holds the water the hull
// displaces, a hull the program moves makes the wake a boat sailing the same line makes, and a
// buoy in the wake rides it.
namespace {

// Archimedes for the patch: the dent it alone would hold, the integral of (p / rho) / g over the
// plane, is the submerged volume hull_of was given (midpoint sum on 2 cm cells over +-4 lengths).
TEST(Step08WakeOnTheSea, TheHullsDentHoldsTheWaterItDisplaces) {
    const double length = 6, volume = 2.1;
    const step08::BoatSettings hull = step08::hull_of(length, volume);
    double dent = 0;
    const double h = 0.02;
    for (double a = -4 * length + h / 2; a < 4 * length; a += h)
        for (double b = -2 * length + h / 2; b < 2 * length; b += h) dent += step08::hull_pressure(hull, {a, b}) / ocean::kGravity * h * h;
    std::printf("draft %.3f m; dent %.6f m^3 for %.1f m^3\n", hull.draft, dent, volume);
    EXPECT_NEAR(dent, volume, 1e-6 * volume);
}

// press() is sail() with the path given: a hull pressed along the straight line a boat sails at
// 4 m/s, frame by frame, leaves the same field, to rounding.
TEST(Step08WakeOnTheSea, AHullMovedByTheProgramMakesTheWakeOfOneSailingTheSameLine) {
    step08::WaveFieldSettings s;
    s.n = 64;
    s.cell = 0.5;
    s.absorbing_width = 4;
    step08::BoatSettings boat;
    step08::WakeScene sailed(s), pressed(s);
    const glm::dvec2 heading = glm::normalize(glm::dvec2(1, 0.5));
    sailed.place({0, 0}, heading);
    pressed.place({0, 0}, heading);
    for (int frame = 0; frame < 80; ++frame) {
        sailed.sail(0.1, boat, 0);
        pressed.press(0.1, (frame + 1) * 0.1 * boat.speed * heading, heading, boat);
    }
    double largest = 0, difference = 0;
    for (std::size_t c = 0; c < sailed.field().heights().size(); ++c) {
        largest = std::max(largest, std::abs(sailed.field().heights()[c]));
        difference = std::max(difference, std::abs(sailed.field().heights()[c] - pressed.field().heights()[c]));
    }
    std::printf("largest height %.3f m, largest difference %.1e m\n", largest, difference);
    EXPECT_GT(largest, 0.05);
    EXPECT_LT(difference, 1e-9 * largest);
}

// A buoy (step07's, 1.2 m) 8 m abeam of the boat's track, on still water with the wake in it
// (SeaWithWake): it rises and falls as the wake's waves pass, at least half as much as the water
// under it (the waves are several times its size: it follows the surface), and at most three
// times: its own period (about 1.3 s) is near the divergent waves' (1.4 to 2 s), and its drag
// (0.5/s) damps it little, so it may overshoot the water, but not run away.
TEST(Step08WakeOnTheSea, ABuoyRidesTheWake) {
    step08::WaveFieldSettings s;
    s.n = 128;
    s.cell = 0.5;
    s.absorbing_width = 8;
    step08::WakeScene scene(s);
    step08::BoatSettings boat;
    boat.draft = 0.5;
    scene.place({-40, 0}, {1, 0});
    step07::BodyParams params;
    const step07::BodySettings buoy_settings = step07::body_settings(params)[step07::kBuoy];
    const step07::FlatSea still;
    // Afloat first: on still water for 20 s (its drag calms it).
    step07::FloatingBody buoy(buoy_settings, {0, 0, 8});
    for (int i = 0; i < 400; ++i) buoy.step(still, still, 0.05);
    const double rest = buoy.position().y;
    step06::ExtraWaveMaps before = step08::wake_maps(scene.field(), 1.0), now;
    double lowest = rest, highest = rest, water_low = 0, water_high = 0;
    for (int i = 0; i < 400; ++i) {  // 20 s: the boat from 40 m before the buoy to 40 m past it
        scene.sail(0.05, boat, 0);
        now = step08::wake_maps(scene.field(), 1.0);
        buoy.step(step08::SeaWithWake(still, before), step08::SeaWithWake(still, now), 0.05);
        before = now;
        lowest = std::min(lowest, buoy.position().y);
        highest = std::max(highest, buoy.position().y);
        const double water = step06::extra_waves_at(now, {buoy.position().x, buoy.position().z}).displacement.y;
        water_low = std::min(water_low, water);
        water_high = std::max(water_high, water);
    }
    std::printf("the buoy moved %.3f m up and down; the water under it %.3f m\n", highest - lowest, water_high - water_low);
    EXPECT_GT(water_high - water_low, 0.05);
    EXPECT_GT(highest - lowest, 0.5 * (water_high - water_low));
    EXPECT_LT(highest - lowest, 3 * (water_high - water_low));
}

// Without the wake (an empty field) the same buoy does not move: whatever moved it above was the
// wake.
TEST(Step08WakeOnTheSea, WithoutTheWakeTheBuoyStaysPut) {
    step07::BodyParams params;
    const step07::FloatingBody afloat = [&] {
        step07::FloatingBody b(step07::body_settings(params)[step07::kBuoy], {0, 0, 8});
        const step07::FlatSea still;
        for (int i = 0; i < 400; ++i) b.step(still, still, 0.05);
        return b;
    }();
    step07::FloatingBody buoy = afloat;
    const step07::FlatSea still;
    const step06::ExtraWaveMaps none;
    for (int i = 0; i < 100; ++i) buoy.step(step08::SeaWithWake(still, none), step08::SeaWithWake(still, none), 0.05);
    EXPECT_NEAR(buoy.position().y, afloat.position().y, 1e-3);
}

}  // namespace
