// Chapter 1's wave math against values worked out by hand.
#include "step01_sine2d/sine_sum.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Step01Waves, WavenumberIsTwoPiOverWavelength) {
    // The notes' w = 2 / wavelength would make a 4 m wave repeat every 2 pi * 4 / 2 = 12.6 m.
    const step01::Wave wave{4.0, 1.0, 0.0};
    EXPECT_DOUBLE_EQ(step01::angular_wavenumber(wave), kPi / 2);
    for (double x : {-3.3, 0.0, 0.7, 12.5})
        EXPECT_NEAR(step01::wave_height(wave, x, 0), step01::wave_height(wave, x + 4.0, 0), 1e-12)
            << "a wave repeats every wavelength";
}

TEST(Step01Waves, PhaseRateIsSpeedTimesWavenumber) {
    const step01::Wave wave{4.0, 2.0, 1.0};  // w = pi/2 rad/m, phi = pi/2 rad/s
    EXPECT_DOUBLE_EQ(step01::phase_rate(wave), kPi / 2);
    EXPECT_NEAR(step01::wave_height(wave, 1.0, 0.0), 2.0, 1e-12);   // 2 sin(pi/2)
    EXPECT_NEAR(step01::wave_height(wave, 0.0, 1.0), -2.0, 1e-12);  // 2 sin(-pi/2)
    EXPECT_NEAR(step01::wave_height(wave, 1.0, 1.0), 0.0, 1e-12);   // 2 sin(0)
    EXPECT_NEAR(step01::wave_height(wave, 2.0, 1.0), 2.0, 1e-12);   // 2 sin(pi/2): the crest moved +1 m
    EXPECT_NEAR(step01::wave_height(wave, 0.5, 0.0), std::sqrt(2.0), 1e-12);  // 2 sin(pi/4)
}

TEST(Step01Waves, CrestsMoveAtTheirSpeed) {
    // With x w - t phi, a crest at x0 is found at x0 + speed * t later (travel towards +x). The
    // notes' x w + t phi would find it at x0 - speed * t.
    const step01::Wave wave{6.0, 1.0, 2.5};
    for (double t : {0.3, 1.7, 40.0})
        EXPECT_NEAR(step01::wave_height(wave, 1.5 + 2.5 * t, t), step01::wave_height(wave, 1.5, 0), 1e-9);
    // Not only equal heights: the crest itself (the first maximum right of x = 0 at t = 0 is at
    // x = 1.5 m, a quarter wavelength) is found by a search over the plot's x range later on.
    for (double t : {0.2, 0.5}) {
        double best_x = 0, best_h = -1;
        for (double x = 0; x < 3.0; x += 1e-4)
            if (step01::wave_height(wave, x, t) > best_h) best_h = step01::wave_height(wave, x, t), best_x = x;
        EXPECT_NEAR(best_x, 1.5 + 2.5 * t, 2e-4) << "t = " << t;
    }
}

TEST(Step01Waves, SumAddsTheWaves) {
    const std::vector<step01::Wave> waves{{4.0, 2.0, 1.0}, {2.0, 0.5, 0.0}};
    // 2 sin(pi/2 * 0.5) + 0.5 sin(pi * 0.5) = sqrt(2) + 0.5
    EXPECT_NEAR(step01::sum_of_sines(waves, 0.5, 0.0), std::sqrt(2.0) + 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(step01::sum_of_sines({}, 0.5, 0.0), 0.0);
}

TEST(Step01Waves, SlopeMatchesCentralDifferences) {
    const std::vector<step01::Wave> waves{{7.0, 1.1, 3.0}, {2.3, 0.4, -1.0}, {0.9, 0.1, 1.2}};
    const double h = 1e-5;
    for (double x : {-5.0, 0.0, 0.37, 8.8})
        for (double t : {0.0, 1.5}) {
            const double numeric =
                (step01::sum_of_sines(waves, x + h, t) - step01::sum_of_sines(waves, x - h, t)) / (2 * h);
            EXPECT_NEAR(step01::sum_of_sines_slope(waves, x, t), numeric, 1e-7);
        }
}

// The curvature the plot draws (show_curvature) is the slope's own rate of change.
TEST(Step01Waves, CurvatureMatchesCentralDifferencesOfTheSlope) {
    const std::vector<step01::Wave> waves{{7.0, 1.1, 3.0}, {2.3, 0.4, -1.0}, {0.9, 0.1, 1.2}};
    const double h = 1e-5;
    for (double x : {-5.0, 0.0, 0.37, 8.8})
        for (double t : {0.0, 1.5}) {
            const double numeric =
                (step01::sum_of_sines_slope(waves, x + h, t) - step01::sum_of_sines_slope(waves, x - h, t)) / (2 * h);
            EXPECT_NEAR(step01::sum_of_sines_curvature(waves, x, t), numeric, 1e-6);
        }
}

TEST(Step01Waves, ReducedPhaseKeepsLongRunsExact) {
    const step01::Wave wave{4.0, 1.0, 1.0};  // phi = pi/2: t = 4 s is one whole period
    const double ten_days = 864000.0;         // a multiple of 4 s
    // Angles compared modulo 2 pi: a phase of -1e-10 comes back as 2 pi - 1e-10, the same angle.
    auto same_angle = [](double a, double b) { return std::abs(std::remainder(a - b, 2 * kPi)) < 1e-6; };
    const double rate = step01::phase_rate(wave);
    EXPECT_TRUE(same_angle(step01::phase_at(rate, ten_days), 0.0)) << step01::phase_at(rate, ten_days);
    EXPECT_NEAR(step01::phase_at(rate, ten_days + 1.0), 1.5 * kPi, 1e-6);  // -pi/2 into [0, 2 pi)
    const step01::Wave backwards{4.0, 1.0, -1.0};
    const double phase = step01::phase_at(step01::phase_rate(backwards), 1.0);
    EXPECT_GE(phase, 0.0);
    EXPECT_LT(phase, 2 * kPi);
    EXPECT_NEAR(phase, 0.5 * kPi, 1e-12);  // -(-pi/2)
}

}  // namespace
