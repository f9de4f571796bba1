// step06's CPU math: cascade bands, foam's frame-rate independence, tessellation levels.
#include "step05_fft/spectrum.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/tessellation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(Step06Cascades, BandsCoverTheResolvedRangeWithoutOverlap) {
    for (int n : {64, 256, 512}) {
        const auto sizes = step06::cascade_patch_sizes(500);
        const auto bands = step06::cascade_bands(sizes, n);
        EXPECT_EQ(bands[0].low, 0.0);
        for (int c = 0; c < step06::kCascades; ++c) {
            const auto& b = bands[std::size_t(c)];
            EXPECT_LT(b.low, b.high) << c;
            if (c + 1 < step06::kCascades) {
                EXPECT_EQ(b.high, bands[std::size_t(c + 1)].low) << "contiguous";
            }
            // Each band lies inside what its own grid resolves: above its first mode (c > 0),
            // below the circle inscribed in its grid, pi N / L.
            if (c > 0) {
                EXPECT_GT(b.low, 2 * step05::kPi / sizes[std::size_t(c)]);
            }
            EXPECT_LE(b.high, step05::kPi * n / sizes[std::size_t(c)] * (1 + 1e-12)) << c;
        }
        EXPECT_DOUBLE_EQ(bands[3].high, step05::kPi * n / sizes[3]);
        // Non-integer ratios: no tile is a whole multiple of another.
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) {
                const double ratio = sizes[std::size_t(a)] / sizes[std::size_t(b)];
                EXPECT_GT(std::abs(ratio - std::round(ratio)), 0.2) << a << "/" << b;
            }
    }
}

TEST(Step06Cascades, NoModeIsCountedTwice) {
    // Every mode of every cascade lies in exactly one band: its own.
    step05::SpectrumParams shared;
    shared.resolution = 64;
    const auto cascades = step06::cascade_spectra(shared);
    const auto bands = step06::cascade_bands(step06::cascade_patch_sizes(shared.patch_size), 64);
    for (int c = 0; c < step06::kCascades; ++c)
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const auto& p = cascades[std::size_t(c)];
                if (!step05::resolved_mode(p, i, j)) continue;
                const double k = std::hypot(step05::wavenumber(i, 64, p.patch_size), step05::wavenumber(j, 64, p.patch_size));
                int owners = 0;
                for (const auto& b : bands) owners += k >= b.low && k < b.high;
                ASSERT_EQ(owners, 1);
                ASSERT_TRUE(k >= bands[std::size_t(c)].low && k < bands[std::size_t(c)].high);
            }
}

TEST(Step06Cascades, SummedVarianceMatchesTheSingleSpectrumIntegral) {
    // Each cascade's resolved variance against the integral of the one spectrum over its band,
    // and their sum against the integral over the whole range [0, pi N / L_3). Energy counted
    // twice (overlapping bands) would show as +100 % in a band, a lost band as a hole.
    // The grids only sample the spectrum. Cascade 0 holds the narrow JONSWAP peak (sigma = 0.07)
    // with dk = 2 pi / 500 m, about 7 samples across k_p: measured 6 % low. Cascades 1-3 sit on
    // the steep tail, whose energy gathers at each band's inner circle (6 dk): the lattice points
    // just inside it count ~4 % more area than the circle has. Stated tolerances: 10 % for
    // cascade 0, 6 % for the others, 8 % for the sum.
    step05::SpectrumParams shared;
    shared.resolution = 256;
    shared.wind_speed = 14;
    const auto cascades = step06::cascade_spectra(shared);
    const auto bands = step06::cascade_bands(step06::cascade_patch_sizes(shared.patch_size), 256);
    auto integral = [&](double k0, double k1) {
        const int steps = 100000;
        const double a = std::log(std::max(k0, 1e-4)), b = std::log(k1);  // in log k: decades
        double sum = 0;
        for (int i = 0; i < steps; ++i) {
            const double k = std::exp(a + (b - a) * (i + 0.5) / steps);
            sum += step05::omnidirectional_k(shared, k) * k * (b - a) / steps;
        }
        return sum;
    };
    double summed = 0;
    for (int c = 0; c < step06::kCascades; ++c) {
        const double discrete = step05::resolved_variance(cascades[std::size_t(c)]);
        const double exact = integral(bands[std::size_t(c)].low, bands[std::size_t(c)].high);
        std::printf("cascade %d: %.6f m^2 on the grid, %.6f m^2 integral (%+.2f%%)\n", c, discrete, exact,
                    100 * (discrete / exact - 1));
        EXPECT_NEAR(discrete / exact, 1.0, c == 0 ? 0.10 : 0.06) << c;
        summed += discrete;
    }
    const double total = integral(0, bands[3].high);
    std::printf("sum: %.5f m^2, integral %.5f m^2 (%+.2f%%)\n", summed, total, 100 * (summed / total - 1));
    EXPECT_NEAR(summed / total, 1.0, 0.08);
}

TEST(Step06Foam, ImpulseDecaysExponentiallyWhateverTheFrameRate) {
    const step06::FoamSettings s;  // J = 1 >= threshold: nothing is injected
    for (double dt : {1.0 / 30, 1.0 / 120}) {
        double foam = 1;
        for (int i = 0; i < int(std::lround(1 / dt)); ++i) foam = step06::foam_step(foam, 1.0, dt, s);
        EXPECT_NEAR(foam / std::exp(-s.decay_rate), 1.0, 1e-9) << "dt = " << dt;
    }
    // Injection is a rate: the foam made in one second hardly depends on the step.
    auto grown = [&](double dt) {
        double foam = 0;
        for (int i = 0; i < int(std::lround(1 / dt)); ++i) foam = step06::foam_step(foam, 0.7, dt, s);
        return foam;
    };
    EXPECT_NEAR(grown(1.0 / 30), grown(1.0 / 120), 0.01);
    EXPECT_NEAR(step06::foam_steady_state(0.7, s), std::min(1.0, s.injection * 0.1 / s.decay_rate), 1e-12);
}

TEST(Step06Tessellation, LevelFallsWithDistance) {
    double previous = step06::kMaxTessLevel + 1;
    for (double d : {1.0, 4.0, 16.0, 64.0, 256.0, 1024.0, 4096.0}) {
        const double level = step06::tessellation_level(d, 16, 12);
        EXPECT_LE(level, previous) << d;
        EXPECT_GE(level, 1.0);
        EXPECT_LE(level, step06::kMaxTessLevel);
        previous = level;
    }
    EXPECT_EQ(step06::tessellation_level(1.0, 16, 12), 64.0);
    EXPECT_EQ(step06::tessellation_level(1e5, 16, 12), 1.0);
    EXPECT_EQ(step06::triangles_for_uniform_level(3.2), 2 * 4 * 4);
}

}  // namespace
