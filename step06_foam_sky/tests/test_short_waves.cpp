// The glitter's slopes: Cox and Munk's fit and Elfouhaily et al.'s short waves by hand, then the
// sum of the simulated cascades and the short waves held to what Cox and Munk photographed.
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/short_waves.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

TEST(Step06ShortWaves, CoxMunkByHand) {
    // U10 = 10 m/s is 10.206 m/s at 12.5 m (log profile, z0 = 2e-4 m).
    const double u = 10 * std::log(12.5 / 2e-4) / std::log(10 / 2e-4);
    EXPECT_NEAR(u, 10.206, 1e-3);
    const auto cm = step06::cox_munk(10);
    EXPECT_NEAR(cm.upwind, 3.16e-3 * u, 1e-12);
    EXPECT_NEAR(cm.crosswind, 0.003 + 1.92e-3 * u, 1e-12);
    // Their total fit, 0.003 + 5.12e-3 U, is the components' sum within its own +-0.004.
    EXPECT_NEAR(cm.total(), 0.003 + 5.12e-3 * u, 0.004);
}

TEST(Step06ShortWaves, CurvatureAtTheCapillaryMinimumByHand) {
    // At k = k_m the bump is 1 and c = sqrt(2 g / k_m) = 0.2303 m/s (c_m, 0.23, is its rounding):
    // B_h = alpha_m / 2 c_m / c times L_PM (1 this far above the peak).
    const double c_ratio = 0.23 / std::sqrt(2 * 9.81 / 370);
    const double u_star = std::sqrt((0.8 + 0.065 * 10) * 1e-3) * 10;  // Wu's C_D
    EXPECT_NEAR(step06::friction_velocity(10), u_star, 1e-12);
    const double alpha_m = 0.01 * (1 + 3 * std::log(u_star / 0.23));  // u* > c_m
    EXPECT_NEAR(step06::short_wave_curvature(370, 10, 0.05), alpha_m / 2 * c_ratio, 1e-9);
    // Below u* = c_m the log is taken once: a light air (U10 = 3 m/s, u* = 0.09 m/s).
    const double light = std::sqrt((0.8 + 0.065 * 3) * 1e-3) * 3;
    const double below_peak = std::exp(-1.25 * (0.5 / 370) * (0.5 / 370));  // L_PM at k_p = 0.5 rad/m
    EXPECT_NEAR(step06::short_wave_curvature(370, 3, 0.5),
                0.5 * 0.01 * (1 + std::log(light / 0.23)) * c_ratio * below_peak, 1e-12);
    EXPECT_EQ(step06::short_wave_curvature(370, 0, 0.5), 0.0) << "no wind, no short waves";
}

TEST(Step06ShortWaves, SpreadingFavoursTheWindAndSplitsTheVarianceExactly) {
    for (double k : {70.0, 370.0, 2000.0}) {
        const double delta = step06::spreading_delta(k, 10, 0.05);
        EXPECT_GT(delta, 0) << k;
        EXPECT_LT(delta, 1) << k;
    }
    const auto v = step06::short_wave_slope_variance(10, 0.05, 70);
    EXPECT_GT(v.upwind, v.crosswind) << "short waves still lean with the wind";
    // The split keeps the whole: the total is the integral of B_h d(ln k), by a finer rule here.
    double total = 0;
    const int steps = 20000;
    const double step = std::log(37000.0 / 70) / steps;
    for (int i = 0; i < steps; ++i) total += step06::short_wave_curvature(70 * std::exp((i + 0.5) * step), 10, 0.05) * step;
    EXPECT_NEAR(v.total(), total, 1e-6 * total);
}

// The observable: the mean square slope the sun's glitter sees on step06's sea (its four cascades
// plus the short waves beyond them) against Cox and Munk's clean-sea fit, U10 = 2 ... 20 m/s.
// Nothing here is fitted to Cox and Munk: the cascades are JONSWAP's (step05) and the short waves
// Elfouhaily et al.'s. Measured: total 0.96-1.09 of theirs, upwind 0.90-1.02 (U >= 5), crosswind
// 1.02-1.18; without the short waves the total is 0.44-0.99 of theirs (0.59 at 10 m/s).
TEST(Step06ShortWaves, TheSeaSlopesAreWhatCoxAndMunkPhotographed) {
    for (double u : {2.0, 3.0, 5.0, 7.5, 10.0, 12.5, 15.0, 17.5, 20.0}) {
        step05::OceanParams params;
        step06::use_default_sea(params);
        params.spectrum.wind_speed = u;
        const auto sea = step06::sea_slope_variance(params.spectrum);
        const auto cm = step06::cox_munk(u), short_waves = step06::short_wave_slope_variance_beyond(params.spectrum);
        std::printf("U10 %4.1f m/s: ours %.4f (upwind %.4f, crosswind %.4f; the short waves %.4f, %.4f), Cox-Munk %.4f (%.4f, %.4f)\n",
                    u, sea.total(), sea.upwind, sea.crosswind, short_waves.upwind, short_waves.crosswind, cm.total(),
                    cm.upwind, cm.crosswind);
        EXPECT_NEAR(sea.total() / cm.total(), 1.0, 0.10) << "U10 = " << u;
        if (u >= 5) {
            EXPECT_NEAR(sea.upwind / cm.upwind, 1.0, 0.10) << "U10 = " << u;
            EXPECT_NEAR(sea.crosswind / cm.crosswind, 1.0, 0.20) << "U10 = " << u;
            EXPECT_GT(sea.upwind, 1.1 * sea.crosswind) << "the glitter is longer along the wind, U10 = " << u;
        }
    }
}

// The slope variance turns with the wind: measured along the wind, whatever its direction.
TEST(Step06ShortWaves, UpwindTurnsWithTheWind) {
    step05::OceanParams params;
    step06::use_default_sea(params);
    params.spectrum.resolution = 64;
    const auto at = [&](double direction) {
        params.spectrum.wind_direction = direction;
        return step06::resolved_slope_variance_by_axis(step06::cascade_spectra(params.spectrum)[1]);
    };
    const auto a = at(30), b = at(120);
    EXPECT_GT(a.upwind, a.crosswind);
    EXPECT_NEAR(a.upwind, b.upwind, 0.05 * a.upwind) << "the same sea turned by 90 degrees";
    EXPECT_NEAR(a.crosswind, b.crosswind, 0.05 * a.crosswind);
}

}  // namespace
