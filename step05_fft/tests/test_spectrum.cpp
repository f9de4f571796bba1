// Chapter 4's spectrum and its CPU transforms, in double precision.
#include "step05_fft/donelan_banner.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/radix2.hpp"
#include "step05_fft/spectrum.hpp"
#include "step05_fft/tests/spectrum_heights.hpp"
#include "step03_lighting/normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

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
    for (Spreading spreading : {Spreading::Hasselmann, Spreading::DonelanBanner})
        for (double ratio : {0.3, 0.7, 1.0, 2.5, 8.0})
            for (double spread : {0.0, 0.2, 1.0})
                for (double swell : {0.0, 0.5, 1.0}) {
                    const int steps = 20000;
                    double sum = 0;
                    for (int i = 0; i < steps; ++i) {
                        const double theta = -kPi + 2 * kPi * (i + 0.5) / steps;
                        sum += directional_spreading(ratio * peak, theta, peak, 10.0, spread, swell, spreading) * 2 *
                               kPi / steps;
                    }
                    // 1e-5, not machine precision: for omega << omega_p the exponent s is ~0.05 and
                    // |cos(theta/2)|^2s has a cusp at theta = pi that slows the midpoint rule down.
                    EXPECT_NEAR(sum, 1.0, 1e-5) << int(spreading) << " " << ratio << " " << spread << " " << swell;
                }
}

TEST(Step05Spreading, TheSech2LobeIsNormalisedOnTheCircle) {
    // Exercise 10's function against the midpoint rule over [-pi, pi], from a lobe that reaches
    // round the circle (beta 0.05: nearly even; 0.40, Banner's short waves) to a narrow one (20).
    // Normalised over the whole line instead (beta / 2) the short waves' lobe would hold 0.85 of
    // their energy, and beta 0.05's a sixth.
    for (double beta : {0.05, 0.4, 1.0, 2.28, 20.0}) {
        const int steps = 200000;
        double sum = 0;
        for (int i = 0; i < steps; ++i) sum += sech2_spreading(-kPi + 2 * kPi * (i + 0.5) / steps, beta) * 2 * kPi / steps;
        EXPECT_NEAR(sum, 1.0, 1e-9) << "beta " << beta;
        EXPECT_GT(sech2_spreading(0.0, beta), sech2_spreading(1.0, beta)) << "peaked along the wind";
        EXPECT_NEAR(sech2_spreading(0.7, beta), sech2_spreading(-0.7, beta), 1e-15) << "symmetric";
    }
}

TEST(Step05Spreading, DonelanBannerIsNarrowestAtThePeak) {
    // Donelan et al. (1985): beta = 2.61 r^1.3 below the peak (r = omega / omega_p), 2.28 r^-1.3
    // above it, continuous at r = 0.95; Banner (1990) beyond r = 1.6, falling towards 10^-0.4.
    EXPECT_NEAR(donelan_banner_beta(0.9, 1.0), 2.61 * std::pow(0.9, 1.3), 1e-12);
    EXPECT_NEAR(donelan_banner_beta(0.95 - 1e-9, 1.0), donelan_banner_beta(0.95, 1.0), 0.01);
    EXPECT_NEAR(donelan_banner_beta(1.0, 1.0), 2.28, 1e-12);
    EXPECT_GT(donelan_banner_beta(1.0, 1.0), donelan_banner_beta(1.3, 1.0));
    EXPECT_GT(donelan_banner_beta(1.3, 1.0), donelan_banner_beta(3.0, 1.0));
    EXPECT_NEAR(donelan_banner_beta(1e4, 1.0), std::pow(10.0, -0.4), 0.01);
    EXPECT_LE(donelan_banner_beta(1e-3, 1.0), 100.0) << "capped far below the peak";
}

TEST(Step05Spreading, DownwindMoreThanUpwindAndSwellNarrows) {
    const double peak = 0.8;
    const double u = 10;
    EXPECT_GT(directional_spreading(peak, 0, peak, u, 0, 0), directional_spreading(peak, kPi / 2, peak, u, 0, 0));
    EXPECT_NEAR(directional_spreading(peak, kPi, peak, u, 0, 0), 0, 1e-12) << "nothing against the wind";
    EXPECT_GT(directional_spreading(peak, 0, peak, u, 0, 1), directional_spreading(peak, 0, peak, u, 0, 0));
    EXPECT_NEAR(directional_spreading(peak, 2.0, peak, u, 1, 0), 1 / (2 * kPi), 1e-15) << "spread 1: even";
}

TEST(Step05Spreading, HasselmannExponentDependsOnTheWaveAge) {
    // Hasselmann et al. (1980): s = 6.97 (w/wp)^4.06 below the peak, 9.77 (w/wp)^mu above it with
    // mu = -2.33 - 1.45 (U wp / g - 1.17). At U wp / g = 1.17 mu is -2.33; a younger sea
    // (U wp / g = 2.17) has mu = -3.78, so its short waves spread wider.
    const double peak = 1.0;
    EXPECT_NEAR(spreading_exponent(0.5, peak, 1.17 * kGravity, 0), 6.97 * std::pow(0.5, 4.06), 1e-12);
    EXPECT_NEAR(spreading_exponent(2.0, peak, 1.17 * kGravity, 0), 9.77 * std::pow(2.0, -2.33), 1e-12);
    EXPECT_NEAR(spreading_exponent(2.0, peak, 2.17 * kGravity, 0), 9.77 * std::pow(2.0, -3.78), 1e-12);
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

TEST(Step05Spectrum, PhillipsPeakIsWhereItsFrequencySpectrumPeaks) {
    // Outside the code: S(omega) = F(k) dk/domega with k = omega^2 / g (deep water) is
    // ~ omega^-5 exp(-(g / (U omega))^4), whose maximum is at omega^4 = (4/5) (g/U)^4. Found here
    // by a search over omega, and held to what the spreading uses as the peak.
    SpectrumParams p;
    p.model = SpectrumModel::Phillips;
    p.depth = 10000;
    for (double u : {6.0, 12.0, 25.0}) {
        p.wind_speed = u;
        double best = 0, best_omega = 0;
        for (double omega = 0.05; omega < 5; omega += 1e-5) {
            const double k = omega * omega / kGravity;
            const double s = phillips_k(k, u) * 2 * omega / kGravity;
            if (s > best) best = s, best_omega = omega;
        }
        EXPECT_NEAR(best_omega, peak_omega_of(p), 2e-5) << "U = " << u;
        EXPECT_NEAR(peak_omega_of(p), std::pow(0.8, 0.25) * kGravity / u, 1e-12);
    }
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

// The chapter's own radix 2 (radix2.hpp: the CPU FFT of the builds without FFTW, such as the Windows
// cross-build) against a closed form and against FFTW, which this build's inverse_fft_2d is.
TEST(Step05Radix2, OneModeIsAPlaneWave) {
    // A single 1 at (kx, kz) transforms to e^{+2 pi i (kx x + kz z) / n} at every (x, z), exactly
    // up to rounding: the inverse's sign and its lack of 1/N, for both axes and the row order.
    const int n = 32, kx = 3, kz = 29;
    std::vector<std::complex<double>> field(std::size_t(n) * n);
    field[std::size_t(kz) * n + kx] = 1.0;
    InverseFft2d<double>(n).field(field.data());
    double worst = 0;
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const double angle = 2 * kPi * (kx * x + kz * z) / n;
            worst = std::max(worst, std::abs(field[std::size_t(z) * n + x] - std::polar(1.0, angle)));
        }
    EXPECT_LT(worst, 1e-13);
}

TEST(Step05Radix2, MatchesFftwOnRandomFields) {
    std::mt19937 random(5);
    std::normal_distribution<double> normal;
    for (int n : {2, 16, 256}) {
        ComplexField input(std::size_t(n) * n);
        for (auto& v : input) v = {normal(random), normal(random)};
        const ComplexField fftw = inverse_fft_2d(input, n);
        std::vector<std::complex<double>> own = input;
        InverseFft2d<double>(n).field(own.data());
        std::vector<std::complex<float>> single(input.begin(), input.end());
        InverseFft2d<float>(n).field(single.data());
        double worst = 0, worst_single = 0, largest = 0;
        for (std::size_t i = 0; i < input.size(); ++i) {
            worst = std::max(worst, std::abs(own[i] - fftw[i]));
            worst_single = std::max(worst_single, std::abs(std::complex<double>(single[i]) - fftw[i]));
            largest = std::max(largest, std::abs(fftw[i]));
        }
        // Double: rounding of log2(n^2) stages; float (the CPU backend's): 1e-6 of the largest value.
        EXPECT_LT(worst, 1e-13 * largest) << "n = " << n;
        EXPECT_LT(worst_single, 1e-6 * largest) << "n = " << n;
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

// The mean of h^2 over the simulated tile, averaged over `seeds` seas.
double measured_height_variance(SpectrumParams p, int seeds) {
    double measured = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        p.seed = std::uint64_t(seed);
        const auto maps = simulate_cpu(initial_spectrum(p), 5.0);
        double sum = 0;
        for (double h : maps[Height]) sum += h * h;
        measured += sum / double(maps[Height].size()) / seeds;
    }
    return measured;
}

TEST(Step05Energy, PiersonMoskowitzVarianceMatchesTheClosedForm) {
    // Truth from outside the code: with gamma = 1 JONSWAP is the Pierson-Moskowitz shape
    // alpha g^2 omega^-5 exp(-5/4 (omega_p/omega)^4), whose integral is alpha g^2 / (5 omega_p^4)
    // (substitute u = (omega_p / omega)^4). The heights of simulated seas must have that variance
    // on a grid that resolves the spectrum: a tile of 10 peak wavelengths (dk = k_p / 10) and
    // 256 modes a side (k up to 12.8 k_p, omega up to 3.6 omega_p: the tail beyond holds
    // 1.25 (omega_p / omega_max)^4 = 0.8 % of the energy, less with the grid's corners).
    SpectrumParams p;
    p.wind_speed = 10;
    p.fetch = 100000;
    p.gamma = 1;
    p.depth = 10000;  // deep water: no finite-depth correction to the dispersion
    const double omega_p = jonswap_peak_omega(p.wind_speed, p.fetch);
    const double k_p = omega_p * omega_p / kGravity;
    p.patch_size = 10 * 2 * kPi / k_p;
    p.resolution = 256;
    const double closed_form = jonswap_alpha(p.wind_speed, p.fetch) * kGravity * kGravity / (5 * std::pow(omega_p, 4));
    const double measured = measured_height_variance(p, 8);
    std::printf("Pierson-Moskowitz (gamma 1, U 10 m/s, F 100 km): variance %.5f m^2 measured (8 seeds), "
                "%.5f m^2 closed form alpha g^2/(5 omega_p^4): ratio %.4f\n",
                measured, closed_form, measured / closed_form);
    // 3 %: the tail above the grid (-0.8 %) and eight seeds' luck (about 1 % one sigma).
    EXPECT_NEAR(measured / closed_form, 1.0, 0.03);
    // The numerical integral the growth-law switch uses agrees with the closed form too.
    EXPECT_NEAR(jonswap_variance_per_alpha(omega_p, 1.0) * jonswap_alpha(p.wind_speed, p.fetch) / closed_form, 1.0,
                1e-6);
}

// U = 12 m/s, F = 300 km: k_p = 0.044 rad/m, 7 lattice steps of a 1000 m tile, in deep water. The
// cut-offs keep an annulus from 2.5 dk (where S is below 1e-4 of its peak) to 60 dk (inside the
// Nyquist circle): the grid covers it fully.
SpectrumParams annulus_sea() {
    SpectrumParams p;
    p.wind_speed = 12;
    p.fetch = 300000;
    p.resolution = 128;
    p.patch_size = 1000;
    p.depth = 10000;
    const double dk = 2 * kPi / p.patch_size;
    p.low_cutoff = 2.5 * dk;
    p.high_cutoff = 60 * dk;
    return p;
}

TEST(Step05Energy, HeightVarianceMatchesTheSpectrumIntegral) {
    // Parseval: the mean of h^2 over the grid is sum |h~(k)|^2, whose expectation is the integral
    // of Phi over the modes the grid carries. The sum is checked against an integral of S(omega)
    // done here in polar coordinates (not the code's resolved_variance), over the annulus the
    // grid covers fully, with the grid restricted to it by the cut-offs.
    SpectrumParams p = annulus_sea();
    double integral = 0;                         // int S(omega) domega over the annulus (D sums to 1)
    const double w0 = dispersion(p.low_cutoff, p.depth), w1 = dispersion(p.high_cutoff, p.depth);
    for (int i = 0; i < 100000; ++i) {
        const double dw = (w1 - w0) / 100000, w = w0 + (i + 0.5) * dw;
        integral += jonswap(w, p.wind_speed, p.fetch, p.gamma) * dw;
    }
    const double measured = measured_height_variance(p, 24);
    std::printf("height variance: %.6f m^2 measured (24 seeds), %.6f m^2 integral of S over the band, "
                "%.6f m^2 sum over the grid's modes\n", measured, integral, resolved_variance(p));
    // 5 %: 24 seeds (about 2 % one sigma) and the lattice's sampling of the narrow JONSWAP peak
    // (gamma 3.3, a few samples across it).
    EXPECT_NEAR(measured / integral, 1.0, 0.05);
    EXPECT_NEAR(resolved_variance(p) / integral, 1.0, 0.03);
}

TEST(Step05Energy, SlopeVarianceIsTheSecondMomentOfTheSpectrum) {
    // E[(dh/dx)^2 + (dh/dz)^2] = integral of |k|^2 Phi d^2k = integral of k^2 F(k) dk (D sums to
    // 1): the grid's sum (what a shader's roughness takes) against that 1D integral, over an annulus
    // the grid covers, as in the height test above.
    const SpectrumParams p = annulus_sea();
    double integral = 0;
    const int steps = 200000;
    for (int i = 0; i < steps; ++i) {
        const double step = (p.high_cutoff - p.low_cutoff) / steps, k = p.low_cutoff + (i + 0.5) * step;
        integral += k * k * omnidirectional_k(p, k) * step;
    }
    std::printf("slope variance: %.6f on the grid, %.6f integral of k^2 F(k)\n", resolved_slope_variance(p), integral);
    EXPECT_NEAR(resolved_slope_variance(p) / integral, 1.0, 0.03);
    EXPECT_DOUBLE_EQ(resolved_moment(p, 0), resolved_variance(p));
}

TEST(Step05Energy, HeightsAgainstObservedGrowth) {
    // U = 10 m/s, F = 100 km. JONSWAP's separately fitted alpha and omega_p give Hs = 4 sqrt(E)
    // of about 2.13 m; the JONSWAP growth law (E g^2 / U^4 = 1.6e-7 g F / U^2) and the Coastal
    // Engineering Manual's fetch-limited formula both give about 1.6 m. Worked by hand:
    // growth law: g F / U^2 = 9810, E = 1.6e-7 * 9810 * 1e4 / 96.236 = 0.16310 m^2, Hs = 1.6154 m;
    // CEM: C_D = 0.00145, u*^2 = 0.145, g F / u*^2 = 6.7655e6, Hm0 = 4.13e-2 * 2601.1 * 0.145 / 9.81 = 1.5878 m.
    const double u = 10, f = 100000;
    const double fitted = 4 * std::sqrt(jonswap_alpha(u, f) * jonswap_variance_per_alpha(jonswap_peak_omega(u, f), 3.3));
    EXPECT_NEAR(fitted, 2.13, 0.02);
    EXPECT_NEAR(4 * std::sqrt(growth_law_variance(u, f)), 1.6154, 1e-3);
    EXPECT_NEAR(cem_significant_height(u, f), 1.5878, 1e-3);
    // The switch: with energy = growth_law the spectrum's own integral follows the growth law.
    for (double gamma : {1.0, 3.3, 7.0}) {
        const JonswapShape shape = jonswap_shape_for(u, f, gamma, JonswapEnergy::GrowthLaw);
        EXPECT_EQ(shape.gamma, gamma) << "below the fully developed sea: gamma as given";
        double integral = 0;
        const double wp = jonswap_peak_omega(u, f);
        for (int i = 0; i < 400000; ++i) {
            const double dw = 40 * wp / 400000, w = 0.2 * wp + (i + 0.5) * dw;
            integral += jonswap_with_alpha(w, shape.alpha, wp, shape.gamma) * dw;
        }
        EXPECT_NEAR(integral / growth_law_variance(u, f), 1.0, 2e-3) << "gamma " << gamma;
    }
}

TEST(Step05Jonswap, TheFetchStopsWhereThePeakReachesPiersonMoskowitz) {
    // 22 (g/U) (gF/U^2)^(-1/3) = 0.855 g/U at gF/U^2 = (22 / 0.855)^3: 25.7310^3 = 17036.1 by hand.
    EXPECT_NEAR(kFullyDevelopedFetch, 17036.1, 0.1);
    for (double u : {4.0, 10.0, 22.0}) {
        EXPECT_NEAR(fully_developed_fetch(u), 17036.1 * u * u / kGravity, 0.1 * u * u / kGravity);
        // At the fully developed fetch and beyond, JONSWAP's peak is Pierson-Moskowitz's.
        for (double times : {1.0, 3.0, 100.0})
            EXPECT_NEAR(jonswap_peak_omega(u, times * fully_developed_fetch(u)), 0.855 * kGravity / u, 1e-12);
        // Below it the fetch is the fetch.
        EXPECT_EQ(developing_fetch(u, 0.5 * fully_developed_fetch(u)), 0.5 * fully_developed_fetch(u));
    }
}

TEST(Step05Energy, NoWindSeaIsHigherThanTheFullyDevelopedOne) {
    // From 2 to 40 m/s, fetches from 1 km to 100 000 km (far past full development at every wind),
    // gamma 1, 3.3 and 7, both energy laws: the spectrum's Hs never passes Pierson-Moskowitz's
    // 0.2202 U^2 / g (1e-4: the two numerical integrals), it grows with the fetch and stops, and
    // as fitted (its alpha passes PM's energy at gF/U^2 = 1.07e4) it ends at PM's height exactly.
    for (JonswapEnergy energy : {JonswapEnergy::Fitted, JonswapEnergy::GrowthLaw})
        for (double gamma : {1.0, 3.3, 7.0})
            for (double u : {2.0, 5.0, 10.0, 14.0, 22.0, 30.0, 40.0}) {
                const double limit = fully_developed_height(u);
                double previous = 0;
                for (double fetch = 1e3; fetch <= 1e8; fetch *= 3.1623) {
                    const double hs = spectrum_height(u, fetch, gamma, energy);
                    EXPECT_LE(hs, limit * (1 + 1e-4)) << "U " << u << " F " << fetch << " gamma " << gamma;
                    EXPECT_GE(hs, previous * (1 - 1e-9))
                        << "U " << u << " F " << fetch << ": the sea grows with the fetch";
                    previous = hs;
                }
                if (energy == JonswapEnergy::Fitted) {
                    EXPECT_NEAR(previous / limit, 1.0, 1e-4) << "U " << u;
                }
            }
}

// A swell is given by its height and period: alone (no wind), the simulated sea's variance is
// (Hs / 4)^2 on a grid that resolves its narrow peak (tile of 10 peak wavelengths), its energy
// travels along swell_direction (the spectrum's mean direction, sum Phi k / |k|), and adding it to
// a wind sea adds the variances (the two spectra are independent).
TEST(Step05Swell, HeightDirectionAndSumAsStated) {
    SpectrumParams p;
    p.wind_speed = 0;  // the swell alone, in deep water
    p.swell_height = 2.5, p.swell_period = 11, p.swell_direction = 250, p.depth = 10000;
    const double wavelength = kGravity * p.swell_period * p.swell_period / (2 * kPi);
    p.patch_size = 10 * wavelength;
    p.resolution = 256;
    const double expected = p.swell_height * p.swell_height / 16;
    const double spectrum = resolved_variance(p), measured = measured_height_variance(p, 8);
    std::printf("swell Hs 2.5 m, 11 s: variance %.5f m^2 (grid sum), %.5f (8 seeds), (Hs/4)^2 = %.5f\n", spectrum,
                measured, expected);
    EXPECT_NEAR(spectrum / expected, 1.0, 0.02);  // the grid's dk resolves the gamma-7 peak within 2 %
    EXPECT_NEAR(measured / expected, 1.0, 0.05);  // and eight seeds' luck (a narrow peak: few modes)
    double cx = 0, cz = 0;
    for (int j = 0; j < p.resolution; ++j)
        for (int i = 0; i < p.resolution; ++i) {
            const double kx = wavenumber(i, p.resolution, p.patch_size), kz = wavenumber(j, p.resolution, p.patch_size);
            const double k = std::hypot(kx, kz);
            if (k <= 0) continue;
            cx += spectrum_2d(p, kx, kz) * kx / k;
            cz += spectrum_2d(p, kx, kz) * kz / k;
        }
    const double direction = std::fmod(std::atan2(cz, cx) * 180 / kPi + 360, 360);
    EXPECT_NEAR(direction, 250, 0.5);
    SpectrumParams wind = p;
    wind.wind_speed = 10;
    wind.swell_height = 0;
    SpectrumParams both = wind;
    both.swell_height = p.swell_height;
    EXPECT_NEAR(resolved_variance(both), resolved_variance(wind) + spectrum, 1e-9 * resolved_variance(both));
    // Longer-crested with a larger s: less energy at 60 degrees off the swell's direction.
    const double k = 2 * kPi / wavelength, off = (250 + 60) * kPi / 180;
    SpectrumParams narrow = p;
    narrow.swell_spreading = 80;
    EXPECT_LT(spectrum_2d(narrow, k * std::cos(off), k * std::sin(off)), spectrum_2d(p, k * std::cos(off), k * std::sin(off)));
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

// The choppy surface's normal: perpendicular to both tangents of P(p) = (p.x + l Dx, h, p.z + l Dz)
// whatever the derivatives, of unit length, up where the surface has not folded (J > 0), and
// step03's normal when l = 0.
TEST(Step05Normal, IsPerpendicularToTheTangentsAndStep03sWithoutChoppiness) {
    std::mt19937 random(4);
    std::uniform_real_distribution<double> uniform(-0.6, 0.6);
    step05::OceanMaps maps;
    maps.n = 1;
    for (auto& field : maps.fields) field.assign(1, 0.0);
    for (int i = 0; i < 1000; ++i) {
        for (step05::Field f : {step05::SlopeX, step05::SlopeZ, step05::DDxDx, step05::DDzDz, step05::DDxDz})
            maps.fields[f][0] = uniform(random);
        const double l = 1.3;
        const auto n = maps.normal(0, l);
        const double xx = 1 + l * maps.fields[step05::DDxDx][0], zz = 1 + l * maps.fields[step05::DDzDz][0];
        const double xz = l * maps.fields[step05::DDxDz][0];
        EXPECT_NEAR(n[0] * xx + n[1] * maps.fields[step05::SlopeX][0] + n[2] * xz, 0.0, 1e-12);  // . dP/dx
        EXPECT_NEAR(n[0] * xz + n[1] * maps.fields[step05::SlopeZ][0] + n[2] * zz, 0.0, 1e-12);  // . dP/dz
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
        if (maps.jacobian(0, l) > 0) {
            EXPECT_GT(n[1], 0.0);
        }
        const auto flat = maps.normal(0, 0.0);
        const step03::Vec3 expected = step03::normal({0.0, maps.fields[step05::SlopeX][0], maps.fields[step05::SlopeZ][0]});
        EXPECT_NEAR(flat[0], expected.x, 1e-12);
        EXPECT_NEAR(flat[1], expected.y, 1e-12);
        EXPECT_NEAR(flat[2], expected.z, 1e-12);
    }
}

// Where the surface folds edge-on the two tangents are parallel and their cross product vanishes:
// the normal must still be a unit vector (normalising zero gave NaN, a black pixel in the stormy
// preset with a bloom halo round it), and ocean_maps.glsl's choppy_normal makes the same guess, up.
TEST(Step05Normal, IsAUnitVectorWhereTheTangentsAreParallel) {
    step05::OceanMaps maps;
    maps.n = 1;
    for (auto& field : maps.fields) field.assign(1, 0.0);
    // dP/dx = (1 + l dDx/dx, 0, l dDx/dz) = (0.5, 0, 0.5) and dP/dz = (0.5, 0, 0.5) with l = 1.
    maps.fields[step05::DDxDx][0] = -0.5;
    maps.fields[step05::DDzDz][0] = -0.5;
    maps.fields[step05::DDxDz][0] = 0.5;
    const auto n = maps.normal(0, 1.0);
    EXPECT_EQ(n[0], 0.0);
    EXPECT_EQ(n[1], 1.0);
    EXPECT_EQ(n[2], 0.0);
}

}  // namespace

// The fully developed sea (Pierson and Moskowitz 1964), the spectra figure's curve: it peaks at
// 0.855 g/U (found by search), its variance is alpha g^2 / (5 omega_p^4) (integrated here by the
// trapezoid rule), so Hs = 0.22 U^2 / g, and no fetch-limited JONSWAP sea at the same wind is
// higher: at 14 m/s over 100 km it peaks later (0.90 rad/s against 0.60) and holds less energy.
TEST(Step05Spectrum, PiersonMoskowitzIsTheFullyDevelopedSea) {
    const double u = 14;
    double best = 0, best_omega = 0, variance = 0, jonswap_variance = 0;
    const double d_omega = 1e-4;
    for (double omega = d_omega; omega < 20; omega += d_omega) {
        const double s = pierson_moskowitz(omega, u);
        if (s > best) best = s, best_omega = omega;
        variance += s * d_omega;
        jonswap_variance += jonswap(omega, u, 100000, 3.3) * d_omega;
    }
    EXPECT_NEAR(best_omega, 0.855 * kGravity / u, 2e-4);
    EXPECT_NEAR(pierson_moskowitz_peak_omega(u), 0.599111, 1e-6);  // 0.855 * 9.81 / 14 by hand
    const double closed_form = kPiersonMoskowitzAlpha * kGravity * kGravity / (5 * std::pow(best_omega, 4));
    EXPECT_NEAR(variance / closed_form, 1.0, 1e-3);
    EXPECT_NEAR(4 * std::sqrt(variance) * kGravity / (u * u), 0.2202, 1e-3);
    EXPECT_GT(variance, jonswap_variance) << "a fetch-limited sea is lower than the fully developed one";
    EXPECT_GT(jonswap_peak_omega(u, 100000), 0.9);
    std::printf("Pierson-Moskowitz at %.0f m/s: peak %.4f rad/s, Hs %.2f m; JONSWAP over 100 km: peak %.4f rad/s, Hs %.2f m\n",
                u, best_omega, 4 * std::sqrt(variance), jonswap_peak_omega(u, 100000), 4 * std::sqrt(jonswap_variance));
}
