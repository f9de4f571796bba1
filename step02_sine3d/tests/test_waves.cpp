// Chapter 1's wave math against values worked out by hand.
#include "step01_sine2d/sine_sum.hpp"
#include "step02_sine3d/waves.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;


TEST(Step02Waves, DirectionIsAnAngleInTheXZPlane) {
    const auto along_x = step02::direction({0, 1, 1, 0});
    EXPECT_NEAR(along_x.x, 1, 1e-15);
    EXPECT_NEAR(along_x.z, 0, 1e-15);
    const auto along_z = step02::direction({90, 1, 1, 0});
    EXPECT_NEAR(along_z.x, 0, 1e-15);
    EXPECT_NEAR(along_z.z, 1, 1e-15);
}

TEST(Step02Waves, HandComputedHeights) {
    // wavelength 2 pi: w = 1. Along +x: h = sin(x); along +z: h = 0.5 sin(z - t).
    const std::vector<step02::DirectionalWave> waves{{0, 2 * kPi, 1.0, 0.0}, {90, 2 * kPi, 0.5, 1.0}};
    EXPECT_NEAR(step02::height(waves, kPi / 2, 0, 0), 1.0, 1e-12);
    EXPECT_NEAR(step02::height(waves, kPi / 2, kPi / 2, 0), 1.5, 1e-12);
    EXPECT_NEAR(step02::height(waves, 0, 0, kPi / 2), -0.5, 1e-12);
    // A diagonal wave (45 degrees) depends on (x + z) / sqrt(2) only.
    const std::vector<step02::DirectionalWave> diagonal{{45, 2 * kPi, 1.0, 0.0}};
    EXPECT_NEAR(step02::height(diagonal, 1.0, 0.0, 0), step02::height(diagonal, 0.0, 1.0, 0), 1e-12);
    EXPECT_NEAR(step02::height(diagonal, 1.0, 1.0, 0), std::sin(std::sqrt(2.0)), 1e-12);
}

TEST(Step02Waves, CrestsTravelAlongTheirDirection) {
    // A direction is where the crests go: the pattern at t is the pattern at 0 moved by speed t d.
    const std::vector<step02::DirectionalWave> waves{{60, 5.0, 1.0, 3.0}};
    const auto d = step02::direction(waves[0]);
    for (double t : {0.4, 2.0})
        EXPECT_NEAR(step02::height(waves, 1.0 + d.x * 3.0 * t, 2.0 + d.z * 3.0 * t, t),
                    step02::height(waves, 1.0, 2.0, 0.0), 1e-9);
    // And the crest itself: along d through the origin, the crest at s = 1.25 m (a quarter of
    // 5 m) at t = 0 is found 3 t further along d at t, the notes' sign would put it 3 t behind.
    for (double t : {0.1, 0.3}) {
        double best_s = 0, best_h = -1;
        for (double s = -2.0; s < 3.5; s += 1e-4) {
            const double h = step02::height(waves, s * d.x, s * d.z, t);
            if (h > best_h) best_h = h, best_s = s;
        }
        EXPECT_NEAR(best_s, 1.25 + 3.0 * t, 2e-4) << "t = " << t;
    }
}

// The ripple (ripple.glsl, the step's ripple_* parameters) held to what a ring of waves must do.
TEST(Step02Ripple, CrestsAreCirclesThatSpreadAtTheirSpeed) {
    const step02::Ripple ripple{3.0, -2.0, 4.0, 0.5, 2.5};
    // The same height in every direction from the centre.
    for (double r : {0.7, 6.0, 23.0})
        for (double angle : {0.3, 2.0, 4.4})
            EXPECT_NEAR(step02::ripple_height(ripple, 3.0 + r * std::cos(angle), -2.0 + r * std::sin(angle), 1.3),
                        step02::ripple_height(ripple, 3.0 + r, -2.0, 1.3), 1e-12);
    // Along a ray, the crest near r = 9 m at t = 0 is 2.5 t further out at t (beyond one wavelength
    // the 1 / sqrt(r) moves the highest point a little: compare t with t + 0.4 s, both measured).
    auto crest_near = [&](double from, double t) {
        double best_r = 0, best_h = -1;
        for (double r = from; r < from + 4.0; r += 1e-4) {
            const double h = step02::ripple_height(ripple, 3.0 + r, -2.0, t);
            if (h > best_h) best_h = h, best_r = r;
        }
        return best_r;
    };
    const double first = crest_near(8.0, 0.0);
    EXPECT_NEAR(crest_near(first - 0.5, 0.4), first + 2.5 * 0.4, 5e-3);
}

TEST(Step02Ripple, CarriesItsEnergyOutwards) {
    // Over a period the height at r swings between +-A(r); the energy crossing a circle of radius r,
    // A(r)^2 2 pi r a second times the speed, is the same for every circle beyond the splash: A^2 r
    // is constant, and A is the ripple's amplitude one wavelength out.
    const step02::Ripple ripple{0.0, 0.0, 4.0, 0.5, 2.5};
    const double period = ripple.wavelength / ripple.speed;
    for (double r : {4.0, 9.0, 30.0, 55.0}) {
        double swing = 0;
        for (double t = 0; t < period; t += period / 4000) swing = std::max(swing, step02::ripple_height(ripple, r, 0.0, t));
        EXPECT_NEAR(swing * swing * r, 0.5 * 0.5 * 4.0, 1e-5) << "r = " << r;
    }
    // Inside one wavelength, the splash: the amplitude itself.
    double swing = 0;
    for (double t = 0; t < period; t += period / 4000) swing = std::max(swing, step02::ripple_height(ripple, 1.5, 0.0, t));
    EXPECT_NEAR(swing, 0.5, 1e-5);
}

TEST(Step02Waves, ReducesToStep01AlongX) {
    const step01::Wave flat{3.0, 0.7, 2.0};
    const std::vector<step02::DirectionalWave> waves{{0, 3.0, 0.7, 2.0}};
    for (double x : {-2.0, 0.1, 5.0})
        EXPECT_NEAR(step02::height(waves, x, 123.0, 0.8), step01::wave_height(flat, x, 0.8), 1e-12);
}

// step02's facet normal: perpendicular to both edges, of unit length, facing up whatever the
// edges' order, and (0, 1, 0) for a level triangle.
TEST(Step02Facet, NormalIsPerpendicularUnitAndUp) {
    const step02::Vector level = step02::facet_normal({1, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(level.x, 0.0, 1e-15);
    EXPECT_NEAR(level.y, 1.0, 1e-15);
    EXPECT_NEAR(level.z, 0.0, 1e-15);
    for (int i = 0; i < 100; ++i) {
        const step02::Vector a{std::cos(i * 0.7), 0.3 * std::sin(i * 1.3), std::sin(i * 0.7)};
        const step02::Vector b{-std::sin(i * 0.9) * 0.8, 0.4 * std::cos(i * 0.5), std::cos(i * 0.9)};
        const step02::Vector n = step02::facet_normal(a, b), swapped = step02::facet_normal(b, a);
        EXPECT_NEAR(n.x * a.x + n.y * a.y + n.z * a.z, 0.0, 1e-12);
        EXPECT_NEAR(n.x * b.x + n.y * b.y + n.z * b.z, 0.0, 1e-12);
        EXPECT_NEAR(n.x * n.x + n.y * n.y + n.z * n.z, 1.0, 1e-12);
        EXPECT_GE(n.y, 0.0);
        EXPECT_NEAR(swapped.x, n.x, 1e-12);
        EXPECT_NEAR(swapped.y, n.y, 1e-12);
    }
}

}  // namespace
