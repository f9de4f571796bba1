// Chapter 3's math: the exp-sine shape and its derivatives, the fBm series, and the exact
// gradient of the domain-warped sum.
#include "step04_fbm/fbm.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using step04::Shape;

TEST(Step04Shape, ExpSineDerivativesMatchCentralDifferences) {
    const double h = 1e-5;
    for (Shape shape : {Shape::Sine, Shape::ExpSine})
        for (double theta : {-3.0, -1.2, 0.0, 0.4, 1.5707963, 2.9, 6.0}) {
            const auto v = step04::wave_shape(shape, theta);
            const auto plus = step04::wave_shape(shape, theta + h), minus = step04::wave_shape(shape, theta - h);
            EXPECT_NEAR(v.first, (plus.value - minus.value) / (2 * h), 1e-9) << theta;
            EXPECT_NEAR(v.second, (plus.first - minus.first) / (2 * h), 1e-9) << theta;
        }
    // exp(sin - 1): 1 at the crest (theta = pi/2), e^-2 in the trough.
    EXPECT_NEAR(step04::wave_shape(Shape::ExpSine, 1.5707963267948966).value, 1.0, 1e-15);
    EXPECT_NEAR(step04::wave_shape(Shape::ExpSine, -1.5707963267948966).value, std::exp(-2.0), 1e-15);
}

TEST(Step04Fbm, AmplitudeAndFrequencySeries) {
    step04::CascadeSettings s;
    s.wave_count = 64;
    s.base_wavelength = 25;
    s.base_amplitude = 0.9;
    s.speed = 1.5;
    const auto waves = step04::fbm_waves(s);
    ASSERT_EQ(waves.size(), 64u);
    const double w0 = step04::kTwoPi / 25;
    for (int i = 0; i < 64; ++i) {
        const auto& w = waves[std::size_t(i)];
        EXPECT_NEAR(w.amplitude, 0.9 * std::pow(0.82, i), 1e-12 * 0.9) << i;
        EXPECT_NEAR(w.wavenumber / (w0 * std::pow(1.18, i)), 1.0, 1e-12) << i;
        EXPECT_NEAR(std::hypot(w.dx, w.dz), 1.0, 1e-15);
        EXPECT_NEAR(w.phase_rate, 1.5 * std::sqrt(9.81 * w.wavenumber), 1e-12) << "deep-water dispersion";
    }
}

TEST(Step04Fbm, DirectionsComeFromTheSeed) {
    step04::CascadeSettings s;
    s.seed = 42;
    const auto a = step04::fbm_waves(s), b = step04::fbm_waves(s);
    s.seed = 43;
    const auto c = step04::fbm_waves(s);
    double spread_x = 0, spread_z = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].dx, b[i].dx);
        spread_x += a[i].dx;
        spread_z += a[i].dz;
    }
    EXPECT_NE(a[0].dx, c[0].dx);
    // Uniform angles: the mean direction of 24 waves is well short of unit length.
    EXPECT_LT(std::hypot(spread_x, spread_z) / double(a.size()), 0.6);
}

TEST(Step04Fbm, WithoutWarpItIsThePlainSum) {
    step04::CascadeSettings s;
    s.wave_count = 10;
    const auto waves = step04::fbm_waves(s);
    const double x = 3.5, z = -7.25, t = 2.0;
    double expected = 0;
    for (const auto& w : waves)
        expected += w.amplitude * std::exp(std::sin((w.dx * x + w.dz * z) * w.wavenumber + w.phase_rate * t) - 1);
    EXPECT_NEAR(step04::cascade_height_gradient(waves, Shape::ExpSine, 0.0, x, z, t).height, expected, 1e-12);
}

TEST(Step04Fbm, WarpedGradientIsExact) {
    // The chain rule through the warp against central differences of the warped height.
    step04::CascadeSettings s;
    s.wave_count = 32;
    const auto cascades = step04::make_cascades(s, 2, 0.37);
    const double h = 1e-5;
    for (Shape shape : {Shape::Sine, Shape::ExpSine})
        for (double warp : {0.0, 2.0, 6.0})
            for (double x : {-20.0, 0.0, 13.3})
                for (double z : {-9.0, 4.4}) {
                    const double t = 1.25;
                    const auto g = step04::height_gradient(cascades, shape, warp, x, z, t);
                    auto height = [&](double px, double pz) {
                        return step04::height_gradient(cascades, shape, warp, px, pz, t).height;
                    };
                    const double dx = (height(x + h, z) - height(x - h, z)) / (2 * h);
                    const double dz = (height(x, z + h) - height(x, z - h)) / (2 * h);
                    EXPECT_NEAR(g.dh_dx, dx, 1e-6) << "warp " << warp << " at " << x << "," << z;
                    EXPECT_NEAR(g.dh_dz, dz, 1e-6) << "warp " << warp << " at " << x << "," << z;
                }
}

TEST(Step04Fbm, WarpChangesTheSurface) {
    step04::CascadeSettings s;
    const auto waves = step04::fbm_waves(s);
    const double plain = step04::cascade_height_gradient(waves, Shape::ExpSine, 0.0, 5, 5, 0).height;
    const double warped = step04::cascade_height_gradient(waves, Shape::ExpSine, 2.0, 5, 5, 0).height;
    EXPECT_GT(std::abs(plain - warped), 1e-3);
}

TEST(Step04Cascades, EachHasItsOwnScaleAndSeed) {
    step04::CascadeSettings s;
    s.base_wavelength = 40;
    s.base_amplitude = 1;
    const auto cascades = step04::make_cascades(s, 3, 0.37);
    ASSERT_EQ(cascades.size(), 3u);
    for (int c = 0; c < 3; ++c) {
        const auto& w0 = cascades[std::size_t(c)].waves.front();
        EXPECT_NEAR(step04::kTwoPi / w0.wavenumber, 40 * std::pow(0.37, c), 1e-9);
        EXPECT_NEAR(w0.amplitude, std::pow(0.37, c), 1e-12);
    }
    EXPECT_NE(cascades[0].waves[0].dx, cascades[1].waves[0].dx);
    // The total is the sum of the cascades.
    const auto total = step04::height_gradient(cascades, Shape::Sine, 0.5, 1, 2, 3);
    double sum = 0;
    for (const auto& c : cascades) sum += step04::cascade_height_gradient(c.waves, Shape::Sine, 0.5, 1, 2, 3).height;
    EXPECT_NEAR(total.height, sum, 1e-12);
}

}  // namespace
