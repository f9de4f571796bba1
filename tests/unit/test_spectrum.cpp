// Chapter 4's spectrum and its CPU transforms, in double precision.
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace step05;

TEST(Step05Dispersion, DeepAndShallowLimits) {
    for (double k : {0.05, 0.3, 2.0}) EXPECT_NEAR(dispersion(k, 5000), std::sqrt(kGravity * k), 1e-12);
    // Shallow water: omega = k sqrt(g h) when k h << 1.
    EXPECT_NEAR(dispersion(0.001, 2.0) / (0.001 * std::sqrt(kGravity * 2.0)), 1.0, 1e-5);
    for (double depth : {3.0, 40.0, 5000.0})
        for (double k : {0.01, 0.2, 1.5}) {
            const double h = 1e-6;
            EXPECT_NEAR(dispersion_derivative(k, depth),
                        (dispersion(k + h, depth) - dispersion(k - h, depth)) / (2 * h), 1e-7);
        }
}

TEST(Step05Jonswap, FetchLimitedParametersByHand) {
    // U = 10 m/s, F = 100 km: U^2/(F g) = 1.01937e-4 -> alpha = 0.076 * 0.13237 = 0.010060;
    // g^2/(U F) = 9.6236e-5 -> omega_p = 22 * 0.045826 = 1.00817 rad/s.
    EXPECT_NEAR(jonswap_alpha(10, 100000), 0.010060, 2e-6);
    EXPECT_NEAR(jonswap_peak_omega(10, 100000), 1.00817, 2e-5);
}

TEST(Step05Jonswap, PeakIsAtOmegaP) {
    for (double gamma : {1.0, 3.3, 7.0}) {
        const double peak = jonswap_peak_omega(15, 300000);
        double best = 0, best_omega = 0;
        for (double omega = 0.2; omega < 3; omega += 1e-5) {
            const double s = jonswap(omega, 15, 300000, gamma);
            if (s > best) { best = s; best_omega = omega; }
        }
        EXPECT_NEAR(best_omega, peak, 2e-5) << "gamma " << gamma;
    }
    EXPECT_EQ(jonswap(1.0, 0.0, 300000, 3.3), 0.0) << "no wind, no waves";
}

TEST(Step05Spreading, IntegratesToOne) {
    const double peak = 0.8;
    for (double ratio : {0.3, 1.0, 2.5})
        for (double spread : {0.0, 0.2, 1.0})
            for (double swell : {0.0, 0.5, 1.0}) {
                const int steps = 20000;
                double sum = 0;
                for (int i = 0; i < steps; ++i) {
                    const double theta = -kPi + 2 * kPi * (i + 0.5) / steps;
                    sum += directional_spreading(ratio * peak, theta, peak, spread, swell) * 2 * kPi / steps;
                }
                // 1e-5, not machine precision: for omega << omega_p the exponent s is ~0.05 and
                // |cos(theta/2)|^2s has a cusp at theta = pi that slows the midpoint rule down.
                EXPECT_NEAR(sum, 1.0, 1e-5) << ratio << " " << spread << " " << swell;
            }
}

TEST(Step05Spreading, DownwindMoreThanUpwindAndSwellNarrows) {
    const double peak = 0.8;
    EXPECT_GT(directional_spreading(peak, 0, peak, 0, 0), directional_spreading(peak, kPi / 2, peak, 0, 0));
    EXPECT_NEAR(directional_spreading(peak, kPi, peak, 0, 0), 0, 1e-12) << "nothing against the wind";
    EXPECT_GT(directional_spreading(peak, 0, peak, 0, 1), directional_spreading(peak, 0, peak, 0, 0));
    EXPECT_NEAR(directional_spreading(peak, 2.0, peak, 1, 0), 1 / (2 * kPi), 1e-15) << "spread 1: even";
}

TEST(Step05Spectrum, TwoDimensionalIntegralIsTheOmnidirectionalOne) {
    // Integrating Phi over a ring of wavenumbers gives the integral of F(k) over the same ring:
    // D integrates to 1 and dkx dkz = k dk dtheta.
    SpectrumParams p;
    const double k0 = 0.03, k1 = 0.5;
    const int steps_k = 4000, steps_theta = 720;
    double two_d = 0, one_d = 0;
    for (int i = 0; i < steps_k; ++i) {
        const double k = k0 + (k1 - k0) * (i + 0.5) / steps_k, dk = (k1 - k0) / steps_k;
        one_d += omnidirectional_k(p, k) * dk;
        for (int j = 0; j < steps_theta; ++j) {
            const double theta = 2 * kPi * (j + 0.5) / steps_theta;
            two_d += spectrum_2d(p, k * std::cos(theta), k * std::sin(theta)) * k * dk * 2 * kPi / steps_theta;
        }
    }
    EXPECT_NEAR(two_d / one_d, 1.0, 1e-6);
}

TEST(Step05Spectrum, PhillipsAndTma) {
    const double largest = 12.0 * 12.0 / kGravity;
    EXPECT_NEAR(phillips_k(0.2, 12), 0.5 * 0.0081 * std::exp(-1 / (0.2 * largest * 0.2 * largest)) / 0.008, 1e-15);
    EXPECT_EQ(tma_attenuation(2.0, 4000), 1.0) << "deep water: no attenuation";
    const double omega_h = 0.5, depth = 10;  // omega_h = omega sqrt(h/g)
    EXPECT_NEAR(tma_attenuation(omega_h / std::sqrt(depth / kGravity), depth), 0.125, 1e-12);
}

TEST(Step05Spectrum, CalmSeaIsFlatAndFinite) {
    SpectrumParams p;
    p.wind_speed = 0;
    p.resolution = 64;
    const auto s = initial_spectrum(p);
    const auto maps = simulate_cpu(s, 3.0);
    for (int f = 0; f < kFieldCount; ++f)
        for (double v : maps.fields[std::size_t(f)]) ASSERT_EQ(v, 0.0) << field_name(Field(f));
    EXPECT_EQ(resolved_variance(p), 0.0);
}

TEST(Step05Spectrum, KZeroAndNyquistModesAreZero) {
    SpectrumParams p;
    p.resolution = 64;
    const auto s = initial_spectrum(p);
    EXPECT_EQ(s.h0[0], Complex(0, 0));
    for (int i = 0; i < 64; ++i) {
        EXPECT_EQ(s.h0[std::size_t(32 * 64 + i)], Complex(0, 0));
        EXPECT_EQ(s.h0[std::size_t(i * 64 + 32)], Complex(0, 0));
    }
}

TEST(Step05Transform, HeightIsRealWithZeroMean) {
    SpectrumParams p;
    p.resolution = 64;
    const auto s = initial_spectrum(p);
    for (double t : {0.0, 7.5}) {
        // The height spectrum alone, not packed: its inverse transform must be real.
        const int n = 64;
        const ComplexField height = height_spectrum(s, t);
        const auto h = inverse_fft_2d(height, n);
        double max_real = 0, max_imag = 0, mean = 0;
        for (const auto& v : h) {
            max_real = std::max(max_real, std::abs(v.real()));
            max_imag = std::max(max_imag, std::abs(v.imag()));
            mean += v.real() / double(h.size());
        }
        EXPECT_LT(max_imag, 1e-12 * max_real);
        EXPECT_LT(std::abs(mean), 1e-12 * max_real);
        // And the packed transform carries the same height in its real part.
        const auto maps = simulate_cpu(s, t);
        for (std::size_t i = 0; i < h.size(); ++i) ASSERT_NEAR(maps[Height][i], h[i].real(), 1e-12 * max_real);
    }
}

TEST(Step05Energy, HeightVarianceMatchesTheSpectrumIntegral) {
    // Parseval: the mean of h^2 over the grid is sum |h~(k)|^2, whose expectation is the resolved
    // integral of Phi. One sea deviates by the luck of its few energetic modes; 48 seeds average it.
    SpectrumParams p;
    p.resolution = 64;
    p.patch_size = 400;
    const double expected = resolved_variance(p);
    double measured = 0;
    const int seeds = 48;
    for (int seed = 1; seed <= seeds; ++seed) {
        p.seed = std::uint64_t(seed);
        const auto maps = simulate_cpu(initial_spectrum(p), 5.0);
        double sum = 0;
        for (double h : maps[Height]) sum += h * h;
        measured += sum / double(maps[Height].size()) / seeds;
    }
    std::printf("height variance: %.6f m^2 measured (48 seeds), %.6f m^2 integral; Hs = 4 sqrt = %.3f m\n",
                measured, expected, 4 * std::sqrt(expected));
    EXPECT_NEAR(measured / expected, 1.0, 0.05);
}

TEST(Step05Validate, RefusesImpossibleParameters) {
    SpectrumParams p;
    EXPECT_EQ(validate(p), "");
    p.resolution = 100;
    EXPECT_NE(validate(p).find("power of two"), std::string::npos);
    p.resolution = 4096;
    EXPECT_NE(validate(p).find("power of two"), std::string::npos);
    p.resolution = 64;
    p.depth = -1;
    EXPECT_NE(validate(p).find("depth"), std::string::npos);
}

}  // namespace
