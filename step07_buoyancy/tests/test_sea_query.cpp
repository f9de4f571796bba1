// The height query against closed forms: one Gerstner wave is a trochoid whose height above any
// world point can be found to machine precision by bisection on its rest position; the maps'
// query against the same wave laid out on texels; the water's velocity against the orbital one.
#include "step07_buoyancy/sea_query.hpp"

#include "common/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace {

using step07::GerstnerSea;
using step07::GerstnerWave;
using step07::Inversion;

// The trochoid's height above world x for a wave along +x: the rest position x0 solves
// x0 - A sin(k x0 - omega t) = x (monotonic for kA < 1), found by bisection to 1e-13 m.
double trochoid_height(const GerstnerWave& w, double x, double time) {
    const double k = w.wavenumber(), a = w.amplitude, wt = w.omega() * time - w.phase;
    const auto drawn_at = [&](double x0) { return x0 - a * std::sin(k * x0 - wt); };
    double lo = x - 2 * a, hi = x + 2 * a;
    for (int i = 0; i < 200 && hi - lo > 1e-13; ++i) {
        const double mid = 0.5 * (lo + hi);
        (drawn_at(mid) < x ? lo : hi) = mid;
    }
    return a * std::cos(k * 0.5 * (lo + hi) - wt);
}

GerstnerWave wave_of_steepness(double ka) {
    GerstnerWave w;
    w.wavelength = 20;
    w.amplitude = ka / w.wavenumber();
    return w;
}

TEST(SeaQuery, NewtonFindsTheTrochoidsHeightInFourSteps) {
    for (double ka : {0.1, 0.3, 0.5, 0.7}) {
        const GerstnerWave w = wave_of_steepness(ka);
        const GerstnerSea sea({w}, 3.7);
        double worst = 0;
        int most_steps = 0;
        for (double x = -10; x < 10; x += 0.173) {
            const step07::SeaPoint q = step07::query(sea, {x, 2.5}, {Inversion::Newton, 4, 1e-7});
            worst = std::max(worst, std::abs(q.height - trochoid_height(w, x, 3.7)));
            most_steps = std::max(most_steps, q.iterations);
        }
        std::cout << "kA " << ka << ": worst " << worst << " m in at most " << most_steps << " steps\n";
        EXPECT_LT(worst, 1e-4) << "kA = " << ka;
        EXPECT_LE(most_steps, 4) << "kA = " << ka;
    }
}

TEST(SeaQuery, WithoutTheInversionTheErrorIsTheHorizontalDisplacementsSize) {
    // h(p) instead of h(x): off by up to about slope x displacement, (kA) A, which at kA = 0.7 is
    // two thirds of the wave's amplitude (measured 0.67 A).
    const GerstnerWave w = wave_of_steepness(0.7);
    const GerstnerSea sea({w}, 3.7);
    double worst = 0;
    for (double x = -10; x < 10; x += 0.173)
        worst = std::max(worst, std::abs(step07::query(sea, {x, 0}, {Inversion::None}).height - trochoid_height(w, x, 3.7)));
    std::cout << "without the inversion: worst " << worst / w.amplitude << " A\n";
    EXPECT_GT(worst, 0.4 * w.amplitude);
    EXPECT_LT(worst, 0.8 * w.amplitude);
}

TEST(SeaQuery, FixedPointConvergesButSlowlyWhereTheWaveIsSteep) {
    // Each step multiplies the error by up to kA: at kA = 0.7 four steps leave millimetres to
    // centimetres; forty reach the tolerance. Newton (above) needs four.
    const GerstnerWave w = wave_of_steepness(0.7);
    const GerstnerSea sea({w}, 3.7);
    double worst_after_four = 0, worst_after_forty = 0;
    for (double x = -10; x < 10; x += 0.173) {
        const double truth = trochoid_height(w, x, 3.7);
        worst_after_four = std::max(worst_after_four,
                                    std::abs(step07::query(sea, {x, 0}, {Inversion::FixedPoint, 4, 1e-9}).height - truth));
        worst_after_forty = std::max(worst_after_forty,
                                     std::abs(step07::query(sea, {x, 0}, {Inversion::FixedPoint, 40, 1e-9}).height - truth));
    }
    EXPECT_GT(worst_after_four, 1e-3);
    EXPECT_LT(worst_after_forty, 1e-4);
}

TEST(SeaQuery, CrossingWavesLandOnThePoint) {
    // Two waves at 70 degrees: the answer's rest position is drawn exactly at p.
    GerstnerWave a = wave_of_steepness(0.4), b = wave_of_steepness(0.3);
    b.wavelength = 13;
    b.amplitude = 0.3 / b.wavenumber();
    b.direction = {std::cos(1.2), std::sin(1.2)};
    b.phase = 0.4;
    const GerstnerSea sea({a, b}, 11.0);
    for (double x = -6; x < 6; x += 0.7)
        for (double z = -6; z < 6; z += 0.9) {
            const step07::SeaPoint q = step07::query(sea, {x, z});
            const glm::dvec3 d = sea.at(q.rest).displacement;
            EXPECT_TRUE(q.converged);
            EXPECT_NEAR(q.rest.x + d.x, x, 1e-6);
            EXPECT_NEAR(q.rest.y + d.z, z, 1e-6);
        }
}

TEST(SeaQuery, WhereTheSeaFoldsTheAnswerSaysSo) {
    // kA = 1.3 with choppiness: the trochoid loops, det J < 0 near the crest.
    const GerstnerSea sea({wave_of_steepness(1.3)}, 0.0);
    int unconverged = 0;
    for (double x = -10; x < 10; x += 0.1) unconverged += step07::query(sea, {x, 0}).converged ? 0 : 1;
    EXPECT_GT(unconverged, 0);
}

TEST(SeaQuery, WaterMovesOnItsOrbit) {
    // A Gerstner particle circles with speed A omega; its velocity is the height's time derivative.
    const GerstnerWave w = wave_of_steepness(0.3);
    const double dt = 1e-5;
    for (double t : {0.0, 1.3, 2.9}) {
        const GerstnerSea before({w}, t), now({w}, t + dt);
        const glm::dvec3 v = step07::water_velocity(before, now, dt, {1.7, 0.0});
        EXPECT_NEAR(glm::length(v), w.amplitude * w.omega(), 1e-4 * w.amplitude * w.omega());
        EXPECT_NEAR(v.y, w.amplitude * w.omega() * std::sin(w.wavenumber() * 1.7 - w.omega() * (t + dt / 2)), 1e-4);
    }
}

// A wave that fits its tile, laid out on n x n texels as step05's maps are.
step07::CascadeMaps maps_of(const GerstnerSea& sea, double tile, int n) {
    step07::CascadeMaps m;
    m.n = n;
    m.tile = tile;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const step07::SurfaceAt s = sea.at(glm::dvec2(i, j) * tile / double(n));
            const float d[4] = {float(s.displacement.x), float(s.displacement.y), float(s.displacement.z), float(s.d_dz.x)};
            const float sl[4] = {float(s.d_dx.y), float(s.d_dz.y), float(s.d_dx.x), float(s.d_dz.z)};
            m.displacement.insert(m.displacement.end(), d, d + 4);
            m.slopes.insert(m.slopes.end(), sl, sl + 4);
        }
    return m;
}

TEST(SeaQuery, MapsAnswerAsTheWaveTheyHold) {
    // Two cascades (tiles 40 m and 11 m, a wave fitting each: k = 2 pi (3, 4) / 40 and 2 pi (2, 0)
    // / 11) summed: the query on the maps is the closed form's within the bilinear filter's error
    // (about 0.5 % of the height at 32 texels a wavelength), anywhere, tiles repeating.
    GerstnerWave a = wave_of_steepness(0.5), b = wave_of_steepness(0.3);
    a.wavelength = 8;
    a.amplitude = 0.5 / a.wavenumber();
    a.direction = {0.6, 0.8};
    b.wavelength = 5.5;
    b.amplitude = 0.3 / b.wavenumber();
    const GerstnerSea sea_a({a}, 0.0), sea_b({b}, 0.0), both({a, b}, 0.0);
    const step07::MapSea maps({maps_of(sea_a, 40, 256), maps_of(sea_b, 11, 64)});
    for (double x = -130; x < 130; x += 7.3) {
        const double truth = step07::query(both, {x, 0.37 * x}).height;
        EXPECT_NEAR(step07::query(maps, {x, 0.37 * x}).height, truth, 0.01 * (a.amplitude + b.amplitude)) << x;
    }
}

TEST(SeaQuery, OrbitsShrinkWithDepthAsEToTheKz) {
    // Airy's (and Gerstner's) closed form: the water resting at z = -depth under the mean surface
    // circles with radius A e^(kz), so its velocity is A omega e^(kz) (k^ cos theta, sin theta)
    // with theta = k.x - omega t. One mode of 20 m, kA = 0.3, along (0.6, 0.8); at depths 0,
    // lambda/8, lambda/4 and lambda/2 that is 1, 0.456, 0.208 and 0.043 of the surface's A omega.
    GerstnerWave w = wave_of_steepness(0.3);
    w.direction = {0.6, 0.8};
    const double k = w.wavenumber(), a_omega = w.amplitude * w.omega();
    const auto expected = [&](glm::dvec2 x, double t, double depth) {
        const double theta = glm::dot(k * w.direction, x) - w.omega() * t;
        const double speed = a_omega * std::exp(-k * depth);
        return glm::dvec3(w.direction.x * std::cos(theta), std::sin(theta), w.direction.y * std::cos(theta)) *
               speed;
    };
    // The same mode on a cascade's maps (a 100 m tile holds it: k = 2 pi (3, 4) / 100), which
    // shrink with the band's wavenumber, here the mode's own: the bilinear filter's error only.
    const auto maps_at = [&](double t) {
        step07::CascadeMaps m = maps_of(GerstnerSea({w}, t), 100, 512);
        m.wavenumber = k;
        return step07::MapSea({m});
    };
    // Difference quotients over dt, held to the closed form at the middle of dt: (omega dt)^2 / 24
    // off, and the maps' floats (1e-7 m) over dt.
    const double dt = 1e-5, dt_maps = 1e-3;
    double worst = 0, worst_maps = 0;
    for (double t : {0.0, 1.3}) {
        const step07::MapSea maps_before = maps_at(t), maps_after = maps_at(t + dt_maps);
        for (double depth : {0.0, w.wavelength / 8, w.wavelength / 4, w.wavelength / 2})
            for (const glm::dvec2 x : {glm::dvec2(1.7, 0.0), glm::dvec2(6.1, -3.4)}) {
                // GerstnerSea, each wave by its own k.
                const glm::dvec3 v =
                    step07::water_velocity(GerstnerSea({w}, t), GerstnerSea({w}, t + dt), dt, x, depth);
                worst = std::max(worst, glm::length(v - expected(x, t + dt / 2, depth)) / a_omega);
                EXPECT_LT(glm::length(v - expected(x, t + dt / 2, depth)), 1e-6 * a_omega)
                    << "depth " << depth << ", t " << t;
                // The maps: within 0.5 % of the surface's speed (64 texels a wavelength).
                const glm::dvec3 m = step07::water_velocity(maps_before, maps_after, dt_maps, x, depth);
                worst_maps =
                    std::max(worst_maps, glm::length(m - expected(x, t + dt_maps / 2, depth)) / a_omega);
                EXPECT_LT(glm::length(m - expected(x, t + dt_maps / 2, depth)), 5e-3 * a_omega)
                    << "maps, depth " << depth << ", t " << t;
            }
    }
    std::cout << "velocity at depth against A omega e^(kz): off by " << worst << " (Gerstner), " << worst_maps
              << " (maps) of A omega\n";
}

}  // namespace
