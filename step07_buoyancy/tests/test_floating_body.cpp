// Bodies on still water against Archimedes and the heave oscillator's closed form; on a moving
// sea against what a sailor sees: a buoy rides the surface, a long raft does not follow short
// waves. Every run is deterministic (fixed frame times).
#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_maps.hpp"
#include "step07_buoyancy/sea_query.hpp"

#include "common/constants.hpp"
#include "step05_fft/spectrum.hpp"
#include "step06_foam_sky/cascades.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace {

using step07::BodySettings;
using step07::FloatingBody;
using step07::ShapeKind;

const step07::FlatSea kCalm;

BodySettings box(glm::dvec3 size, double density, double drag = 0.5) {
    BodySettings s;
    s.shape = {ShapeKind::Box, size};
    s.density = density;
    s.linear_drag = drag;
    s.angular_drag = 1.0;
    return s;
}

void run(FloatingBody& body, double seconds, double dt) {
    for (double t = 0; t < seconds - 1e-9; t += dt) body.step(kCalm, kCalm, dt);
}

TEST(FloatingBody, ABoxFloatsAtArchimedesDraft) {
    // Draft d = (rho_b / rho_w) height: the displaced water weighs what the box weighs.
    for (double density : {200.0, 500.0, 900.0}) {
        FloatingBody body(box({2, 1, 3}, density), {0, 0.3, 0});
        run(body, 40, 1.0 / 60);
        const double draft = 0.5 - body.position().y;  // the water at 0, the bottom half a metre below the centre
        const double expected = density / step07::kWaterDensity * 1.0;
        std::cout << "box, density " << density << ": draft " << draft << " m, Archimedes " << expected << " m\n";
        EXPECT_NEAR(draft, expected, 0.01 * expected) << "density " << density;
        EXPECT_NEAR(body.submerged_volume(), density / step07::kWaterDensity * 6.0, 0.01 * 6.0 * density / step07::kWaterDensity);
    }
}

TEST(FloatingBody, ADenserBodySinks) {
    FloatingBody body(box({1, 1, 1}, 1400), {0, 0, 0});
    run(body, 10, 1.0 / 60);
    EXPECT_LT(body.position().y, -5.0);
    EXPECT_LT(body.velocity().y, 0.0);
}

// The spherical cap of depth d holds pi d^2 (3 r - d) / 3: the draft that displaces `volume`.
double cap_depth(double radius, double volume) {
    double lo = 0, hi = 2 * radius;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (ocean::kPi * mid * mid * (3 * radius - mid) / 3 < volume ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

TEST(FloatingBody, TheSphericalCapIsTheSumOfItsSlices) {
    // The cap of draft d: the discs pi (2 r z - z^2) from the bottom up to d, summed here (midpoints);
    // half way up a hemisphere, 2/3 pi r^3; all the way the sphere, 4/3 pi r^3; nothing when dry.
    const double r = 0.6;
    for (double d : {0.05, 0.3, 0.6, 0.9, 1.15}) {
        double slices = 0;
        const int steps = 100000;
        for (int i = 0; i < steps; ++i) {
            const double z = (i + 0.5) * d / steps;
            slices += ocean::kPi * (2 * r * z - z * z) * d / steps;
        }
        EXPECT_NEAR(step07::spherical_cap_volume(r, d), slices, 1e-9) << "draft " << d;
    }
    EXPECT_NEAR(step07::spherical_cap_volume(r, r), 2.0 / 3 * ocean::kPi * r * r * r, 1e-12);
    EXPECT_NEAR(step07::spherical_cap_volume(r, 5.0), 4.0 / 3 * ocean::kPi * r * r * r, 1e-12);
    EXPECT_EQ(step07::spherical_cap_volume(r, -0.1), 0.0);
    // Through the centre, up, rho_w g V.
    const glm::dvec3 f = step07::sphere_buoyancy(r, 0.0, 0.0);
    EXPECT_NEAR(f.y, step07::kWaterDensity * ocean::kGravity * 2.0 / 3 * ocean::kPi * r * r * r, 1e-9);
    EXPECT_EQ(f.x, 0.0);
    EXPECT_EQ(f.z, 0.0);
}

// The angle (degrees) an orientation has turned from upright.
double tilt_degrees(const glm::dquat& q) {
    return 2 * std::acos(std::min(1.0, std::abs(q.w))) * 180 / ocean::kPi;
}

TEST(FloatingBody, EveryBuoySettlesAtItsCapAndStaysUpright) {
    // The program's buoy (1.2 m, built from 6 cells a side as the program builds it) dropped from
    // 0.3 m into still water, for every density from 100 to 1000 kg/m^3: after 40 s its draft is
    // the cap's that displaces its weight (bisection above) within 1 %, it has not turned (1
    // degree), and 20 s later it is still there and still upright; second by second its energy
    // (the cap's buoyancy potential included) never grows. A uniform sphere feels no
    // buoyant torque about its centre; built from cells its draft was off by -5.6 % to +2.5 %, and
    // the cells' staircase rolled it over at some densities.
    const double diameter = 1.2, radius = 0.6;
    for (double density = 100; density <= 1000; density += 100) {
        BodySettings s;
        s.shape = {ShapeKind::Sphere, glm::dvec3(diameter)};
        s.density = density;
        s.cells_per_side = 6;
        FloatingBody body(s, {2, 0.3, -1});
        const double expected =
            cap_depth(radius, density / step07::kWaterDensity * step07::shape_volume(s.shape));
        // Second by second its energy (with the cap's buoyancy potential) never grows.
        double energy = body.energy_in_still_water();
        for (int second = 1; second <= 60; ++second) {
            run(body, 1.0, 1.0 / 60);
            EXPECT_LE(body.energy_in_still_water(), energy + 1e-9 * std::abs(energy))
                << "density " << density;
            energy = body.energy_in_still_water();
            if (second != 40 && second != 60) continue;
            const double draft = radius - body.position().y;
            std::cout << "buoy, density " << density << ": draft " << draft << " m, cap " << expected
                      << " m, turned " << tilt_degrees(body.orientation()) << " degrees\n";
            EXPECT_NEAR(draft, expected, 0.01 * expected) << "density " << density;
            EXPECT_LT(tilt_degrees(body.orientation()), 1.0) << "density " << density;
            EXPECT_LT(glm::length(glm::dvec2(body.position().x - 2, body.position().z + 1)), 1e-3)
                << "no drift";
        }
    }
}

TEST(FloatingBody, BallastMovesTheAxesAsTheParallelAxisTheoremSays) {
    // A 2 x 1 x 3 m box whose mass sits 0.2 m below its middle: about its centre of mass the roll
    // inertia is the box's own, m (1 + 9) / 12, plus m 0.2^2 (Steiner). Its inertia is then summed
    // from the cells; an impulse of 1 N s along z, 1 m above the centre of mass, spins it at
    // 1 / I_xx rad/s about x.
    BodySettings s = box({2, 1, 3}, 500);
    s.ballast = {0, -0.2, 0};
    FloatingBody body(s, {0, 0, 0});
    body.push({0, 0, 1}, {0, 1, 0});
    const double m = body.mass(), expected = 1 / (m * (1 + 9) / 12.0 + m * 0.2 * 0.2);
    EXPECT_NEAR(body.angular_velocity().x, expected, 1e-9 * expected);
    EXPECT_NEAR(body.angular_velocity().y, 0.0, 1e-12);
    EXPECT_NEAR(body.angular_velocity().z, 0.0, 1e-12);
}

TEST(FloatingBody, ABallastedHullRightsItselfAndALightOneLists) {
    // The hull (hull_half_beam: fine bow, V bottom), 9 x 1.5 x 3 m, heeled 0.3 rad and dropped.
    // It displaces its weight (1 %). With its mass a quarter of its depth below the volume's
    // centroid (ballast) it comes back upright, within 5 degrees; of uniform density its mass is
    // too high (the V bottom carries the volume up), and it settles at a list (measured 19 degrees).
    const auto settle = [](glm::dvec3 ballast) {
        BodySettings s;
        s.shape = {ShapeKind::Hull, {9, 1.5, 3}};
        s.density = 300;
        s.cells_per_side = 8;
        s.ballast = ballast;
        FloatingBody body(s, {0, 0.5, 0}, glm::angleAxis(0.3, glm::dvec3(1, 0, 0)));
        run(body, 40, 1.0 / 60);
        EXPECT_NEAR(body.submerged_volume(), 300 / step07::kWaterDensity * body.volume(), 0.01 * body.volume() * 300 / step07::kWaterDensity);
        EXPECT_GT(body.volume(), 0.3 * 9 * 1.5 * 3);  // a hull, not a sliver
        EXPECT_LT(body.volume(), 0.8 * 9 * 1.5 * 3);  // nor a box
        return (body.orientation() * glm::dvec3(0, 1, 0)).y;  // the deck's normal, up
    };
    EXPECT_GT(settle({0, -0.375, 0}), std::cos(5 * ocean::kPi / 180));
    EXPECT_LT(settle({0, 0, 0}), std::cos(10 * ocean::kPi / 180));
}

// Upward zero crossings of y - mean after `skip` seconds: the mean period.
double heave_period(const std::vector<double>& y, double dt, double mean) {
    std::vector<double> crossings;
    for (std::size_t i = 1; i < y.size(); ++i)
        if (y[i - 1] < mean && y[i] >= mean) crossings.push_back((double(i) - (y[i] - mean) / (y[i] - y[i - 1])) * dt);
    if (crossings.size() < 3) return 0;
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

TEST(FloatingBody, ABoxHeavesWithThePeriodOfItsSpring) {
    // Raised 5 cm from its draft d and let go: m y'' = -rho_w g A y - c y', c = m * linear_drag
    // (the drag is per kilogram of water displaced, which at rest is the body's mass). Period
    // 2 pi / sqrt(g / d - (drag / 2)^2): 2 pi sqrt(d / g) without drag. No added mass in the model:
    // the model's own closed form, not a real box's, which carries about 0.8 of its mass of water
    // along and heaves about a third more slowly (motion.md, section 10).
    const double density = 600, drag = 0.2;
    const double draft = density / step07::kWaterDensity;
    FloatingBody body(box({2, 1, 2}, density, drag), {0, 0.5 - draft + 0.05, 0});
    const double dt = 1.0 / 240;
    std::vector<double> y;
    for (int i = 0; i < 240 * 12; ++i) {
        body.step(kCalm, kCalm, dt);
        y.push_back(body.position().y);
    }
    const double expected = ocean::kTwoPi / std::sqrt(ocean::kGravity / draft - drag * drag / 4);
    std::cout << "heave period " << heave_period(y, dt, 0.5 - draft) << " s, predicted " << expected << " s\n";
    EXPECT_NEAR(heave_period(y, dt, 0.5 - draft), expected, 0.05 * expected);
    // It decays, about as e^(-drag t / 2) (0.33 after 11 s): the last second's swing is less than
    // half the first's.
    const auto swing = [&](std::size_t from) {
        const auto [lo, hi] = std::minmax_element(y.begin() + long(from), y.begin() + long(from + 240));
        return *hi - *lo;
    };
    EXPECT_LT(swing(y.size() - 240), 0.5 * swing(0));
}

TEST(FloatingBody, AddedMassSlowsTheHeaveAsTheSpringSays) {
    // motion.md section 10: a box carries water as it heaves, about 1960 kg for this 2400 kg box
    // (a disc of its waterplane's area), and a real box heaves about 1.35 times more slowly. With
    // set_heave_added_mass the whole vertical force moves m + A: (m + A) y'' = -rho_w g S y - c y',
    // c = m drag, so the period is 2 pi / sqrt(g/d m/(m + A) - (drag m / (2 (m + A)))^2).
    const double density = 600, drag = 0.2, added = 1960;
    const double draft = density / step07::kWaterDensity;
    FloatingBody body(box({2, 1, 2}, density, drag), {0, 0.5 - draft + 0.05, 0});
    body.set_heave_added_mass(added);
    const double dt = 1.0 / 240, m = body.mass(), share = m / (m + added);
    std::vector<double> y;
    for (int i = 0; i < 240 * 16; ++i) {
        body.step(kCalm, kCalm, dt);
        y.push_back(body.position().y);
    }
    const double decay = drag * share / 2;
    const double expected = ocean::kTwoPi / std::sqrt(ocean::kGravity / draft * share - decay * decay);
    std::cout << "heave period with " << added << " kg of water " << heave_period(y, dt, 0.5 - draft)
              << " s, predicted " << expected << " s\n";
    EXPECT_NEAR(heave_period(y, dt, 0.5 - draft), expected, 0.05 * expected);
    const double bare = ocean::kTwoPi / std::sqrt(ocean::kGravity / draft - drag * drag / 4);
    EXPECT_NEAR(expected / bare, 1.35, 0.02);  // the README's "a third longer"
}

TEST(FloatingBody, AWaterPushHeldOverAStepMovesItAsItsSubstepsWould) {
    // With Archimedes off, a push of the body's weight given after each step (add_water_push)
    // must undo gravity exactly: the substeps move a constant acceleration's body dt^2 (n + 1) / (2n)
    // (travel_per_acceleration), and the push moves it that far back. Out of the water, at two frame
    // times (two and five substeps), the body stays where it is.
    for (const double dt : {1.0 / 60, 1.0 / 25}) {
        FloatingBody body(box({1, 1, 1}, 500), {0, 5, 0});
        body.set_archimedes(false);
        for (int i = 0; i < 200; ++i) {
            body.step(kCalm, kCalm, dt);
            body.add_water_push({0, body.mass() * ocean::kGravity, 0}, glm::dvec3(0.0), dt);
        }
        EXPECT_NEAR(body.position().y, 5.0, 1e-9) << "dt " << dt;
        EXPECT_NEAR(body.velocity().y, 0.0, 1e-9) << "dt " << dt;
    }
}

TEST(FloatingBody, ASphereHeavesWithThePeriodOfItsWaterplane) {
    // The program's buoy (1.2 m) raised 2 cm above its rest and let go heaves with
    // sphere_heave_period (exercise 3): the period the simulation shows, from its zero crossings,
    // holds the closed form to the program's own integration of the exact cap, at three densities
    // (a shallow cap, a hemisphere, a deep one) and two drags, within 1 % (the box's g / d, which
    // forgets that the sphere's waterplane shrinks, is 24 % off for the hemisphere).
    const double diameter = 1.2, radius = 0.6;
    for (double density : {250.0, 500.0, 800.0})
        for (double drag : {0.1, 0.5}) {
            BodySettings s;
            s.shape = {ShapeKind::Sphere, glm::dvec3(diameter)};
            s.density = density;
            s.linear_drag = drag;
            const double draft = cap_depth(radius, density / step07::kWaterDensity * step07::shape_volume(s.shape));
            FloatingBody body(s, {0, radius - draft + 0.02, 0});
            const double dt = 1.0 / 240;
            std::vector<double> y;
            for (int i = 0; i < 240 * 10; ++i) {
                body.step(kCalm, kCalm, dt);
                y.push_back(body.position().y);
            }
            const double measured = heave_period(y, dt, radius - draft);
            const double expected = step07::sphere_heave_period(radius, draft, drag);
            std::cout << "buoy, density " << density << ", drag " << drag << ": heave period " << measured
                      << " s, predicted " << expected << " s\n";
            EXPECT_NEAR(measured, expected, 0.01 * expected) << "density " << density << ", drag " << drag;
        }
    // Too much drag for the spring: no oscillation, no period.
    EXPECT_TRUE(std::isinf(step07::sphere_heave_period(radius, 1.1, 20.0)));
}

TEST(FloatingBody, ADropDiesDownAtEveryFrameTime) {
    // Dropped from 2 m into still water, tipped: at 240 down to 10 frames a second the energy
    // (kinetic, gravity's and buoyancy's potential) never grows from one second to the next, and
    // the box settles where Archimedes puts it. Explicit Euler gained energy here (its oscillator
    // spirals outwards); semi-implicit Euler keeps it within a bounded band (it conserves a nearby
    // energy exactly, not this one), and the drag takes it.
    for (double dt : {1.0 / 240, 1.0 / 60, 1.0 / 30, 1.0 / 10}) {
        FloatingBody body(box({2, 0.6, 3}, 400), {0, 2, 0}, glm::angleAxis(0.3, glm::dvec3(0.6, 0, 0.8)));
        double previous = body.energy_in_still_water();
        const double dropped_with = previous;
        for (int second = 0; second < 30; ++second) {
            run(body, 1.0, dt);
            const double energy = body.energy_in_still_water();
            EXPECT_LE(energy, previous + 1e-4 * std::abs(dropped_with)) << "dt " << dt << ", second " << second;
            previous = energy;
        }
        EXPECT_LT(glm::length(body.velocity()), 0.01) << "dt " << dt;
        EXPECT_NEAR(0.3 - body.position().y, 0.6 * 400 / step07::kWaterDensity, 0.005) << "dt " << dt;
    }
}

// A JONSWAP sea as the renderer simulates it (step06's four cascades, here at 64 x 64 in double).
// Each cascade's orbits shrink with depth by its band's wavenumber (band_wavenumbers).
struct JonswapSea {
    step05::SpectrumParams params;
    std::vector<step05::InitialSpectrum> cascades;
    std::vector<double> wavenumbers;
    double choppiness = 1.0;
    explicit JonswapSea(double wind_speed, int resolution = 64) {
        params.wind_speed = wind_speed;
        params.resolution = resolution;
        params.patch_size = 250;
        for (const auto& c : step06::cascade_spectra(params)) cascades.push_back(step05::initial_spectrum(c));
        wavenumbers = step07::band_wavenumbers(params);
    }
    step07::MapSea at(double time) const {
        return step07::reference_sea(cascades, time, choppiness, wavenumbers);
    }
    // Linear theory's water `depth` metres down, mode by mode: every amplitude times e^(-|k| depth)
    // (the orbits there), the surface of that sea being the motion at that depth.
    step07::MapSea at_depth_exactly(double time, double depth) const {
        std::vector<step05::InitialSpectrum> shrunk = cascades;
        for (auto& c : shrunk)
            for (int j = 0; j < c.n; ++j)
                for (int i = 0; i < c.n; ++i) {
                    const double k = std::hypot(step05::wavenumber(i, c.n, c.patch_size),
                                                step05::wavenumber(j, c.n, c.patch_size));
                    c.h0[std::size_t(j) * std::size_t(c.n) + std::size_t(i)] *= std::exp(-k * depth);
                }
        return step07::reference_sea(shrunk, time, choppiness);
    }
};

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= double(a.size()), mb /= double(b.size());
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma), bb += (b[i] - mb) * (b[i] - mb);
    return ab / std::sqrt(aa * bb);
}
double variance(const std::vector<double>& a) {
    double m = 0, v = 0;
    for (double x : a) m += x;
    m /= double(a.size());
    for (double x : a) v += (x - m) * (x - m);
    return v / double(a.size());
}

TEST(FloatingBody, ABuoyRidesTheSeaAndARaftSmoothsIt) {
    // 60 s of a 7 m/s JONSWAP sea at 10 frames a second (over step05's default 100 km it is fully
    // developed: Pierson-Moskowitz's peak 0.855 g/U, wavelength 2 pi g / omega_p^2 = 43 m): a
    // 0.6 m buoy's heave follows the surface under it (correlation > 0.98) and it does not tumble
    // (no torque turns a uniform sphere: under 1 degree); a 160 m raft, 3.7 peak wavelengths,
    // heaves less than half the surface's variance at its centre.
    const JonswapSea jonswap(7);
    BodySettings buoy_settings;
    buoy_settings.shape = {ShapeKind::Sphere, glm::dvec3(0.6)};
    buoy_settings.density = 400;
    buoy_settings.cells_per_side = 6;
    buoy_settings.linear_drag = 2.0;  // a buoy damped by its mooring and skirt: at 0.5 it rings at its own
                                      // heave period after the short waves kick it (0.973)
    FloatingBody buoy(buoy_settings, {3, 0, 5});
    BodySettings raft_settings = box({160, 1, 160}, 500);
    raft_settings.cells_per_side = 12;
    FloatingBody raft(raft_settings, {0, 0, 0});
    const double dt = 0.1;
    std::vector<double> buoy_y, surface_at_buoy, raft_y, surface_at_raft;
    double buoy_tilt = 0;
    step07::MapSea before = jonswap.at(0);
    for (int frame = 1; frame <= 600; ++frame) {
        const step07::MapSea now = jonswap.at(frame * dt);
        buoy.step(before, now, dt);
        raft.step(before, now, dt);
        buoy_tilt = std::max(buoy_tilt, tilt_degrees(buoy.orientation()));
        if (frame > 100) {  // after the drop has settled
            buoy_y.push_back(buoy.position().y);
            surface_at_buoy.push_back(step07::query(now, {buoy.position().x, buoy.position().z}).height);
            raft_y.push_back(raft.position().y);
            surface_at_raft.push_back(step07::query(now, {raft.position().x, raft.position().z}).height);
        }
        before = now;
    }
    std::cout << "buoy-surface correlation " << correlation(buoy_y, surface_at_buoy)
              << ", raft heave variance / surface's " << variance(raft_y) / variance(surface_at_raft)
              << ", the buoy turned at most " << buoy_tilt << " degrees\n";
    EXPECT_LT(buoy_tilt, 1.0);
    EXPECT_GT(correlation(buoy_y, surface_at_buoy), 0.98);
    EXPECT_LT(variance(raft_y), 0.5 * variance(surface_at_raft));
    EXPECT_GT(variance(surface_at_raft), 0.01) << "a sea, not a calm";
}

TEST(FloatingBody, TheWaterDeepDownHardlyMoves) {
    // step06's 14 m/s sea (the program's; peak wavelength 76 m). Each cascade's orbits shrink with
    // one wavenumber: the peak's for the band that holds it, the lower edge for the others.
    const JonswapSea sea(14);
    const double k_p = std::pow(step05::jonswap_peak_omega(14, sea.params.fetch), 2) / ocean::kGravity;
    const auto bands = step06::cascade_spectra(sea.params);
    EXPECT_NEAR(sea.wavenumbers[0], k_p, 1e-6 * k_p);
    for (std::size_t c = 1; c < bands.size(); ++c) EXPECT_DOUBLE_EQ(sea.wavenumbers[c], bands[c].low_cutoff);
    // The water's speed (rms over 400 points of a 200 m square, the speed of its motion over
    // 0.1 s) at 0, 5, 10 and 25 m down, against linear theory mode by mode (every mode's orbit
    // times e^(-|k| depth), the same sea).
    const double dt = 0.1, t = 7;
    const step07::MapSea before = sea.at(t), now = sea.at(t + dt);
    const auto rms_speed = [&](const step07::Surface& a, const step07::Surface& b, double depth) {
        double sum = 0;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) {
                const glm::dvec3 v = step07::water_velocity(a, b, dt, {10.0 * i, 10.0 * j}, depth);
                sum += glm::dot(v, v) / 400;
            }
        return std::sqrt(sum);
    };
    // One wavenumber a band lets the band's shorter waves reach too deep: from the surface (exact)
    // down to 25 m, a third of the peak wavelength, the speed is at most 35 % too high (measured
    // 12-28 %) and never too low; at 50 m, where the waves longer than the peak are what is left,
    // it is too low, by less than 1 % of the surface's speed. (The band's energy-weighted mean
    // wavenumber instead: right at 2 m, but a quarter of the motion at 25 m.)
    const double surface = rms_speed(before, now, 0);
    for (double depth : {0.0, 2.0, 5.0, 10.0, 25.0, 50.0}) {
        const double ours = rms_speed(before, now, depth);
        const double truth =
            rms_speed(sea.at_depth_exactly(t, depth), sea.at_depth_exactly(t + dt, depth), 0);
        std::cout << depth << " m down: the water moves at " << ours << " m/s rms, linear theory " << truth
                  << " m/s, the surface " << surface << " m/s\n";
        if (depth <= 25) {
            EXPECT_GE(ours, truth * (1 - 1e-9)) << depth << " m";
            EXPECT_LE(ours, 1.35 * truth) << depth << " m";
        } else {
            EXPECT_NEAR(ours, truth, 0.01 * surface) << depth << " m";
        }
    }
    // A body that sinks (a 1.2 m sphere, 1100 kg/m^3) is carried sideways by the water around it,
    // not by the surface's: passing 20-30 m down its horizontal speed is under 0.1 m/s (measured
    // 0.03; with the surface's motion at every depth, 0.29 in this sea).
    BodySettings s;
    s.shape = {ShapeKind::Sphere, glm::dvec3(1.2)};
    s.density = 1100;
    FloatingBody body(s, {40, 0, 60});
    step07::MapSea previous = sea.at(0);
    double fastest = 0;
    for (int frame = 1; frame <= 400 && body.position().y > -30; ++frame) {
        const step07::MapSea next = sea.at(frame * dt);
        body.step(previous, next, dt);
        if (body.position().y < -20)
            fastest = std::max(fastest, glm::length(glm::dvec2(body.velocity().x, body.velocity().z)));
        previous = next;
    }
    std::cout << "a sinking sphere, 20-30 m down: at most " << fastest << " m/s sideways\n";
    EXPECT_LT(body.position().y, -30) << "it sank";
    EXPECT_LT(fastest, 0.1);
}

}  // namespace
