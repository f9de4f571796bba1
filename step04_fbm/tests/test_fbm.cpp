// Chapter 3's math: the exp-sine shape and its derivatives, the fBm series, and the exact
// gradient of the domain-warped sum.
#include "common/camera.hpp"
#include "step04_fbm/fbm.hpp"
#include "step04_fbm/fbm_params.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using step04::Shape;

TEST(Step04Shape, ExpSineDerivativesMatchCentralDifferences) {
    const double h = 1e-5;
    for (Shape shape : {Shape::Sine, Shape::ExpSine, Shape::PowerSine})
        for (double theta : {-3.0, -1.2, 0.0, 0.4, 1.5707963, 2.9, 6.0}) {
            const auto v = step04::wave_shape(shape, theta);
            const auto plus = step04::wave_shape(shape, theta + h), minus = step04::wave_shape(shape, theta - h);
            EXPECT_NEAR(v.first, (plus.value - minus.value) / (2 * h), 1e-9) << theta;
            EXPECT_NEAR(v.second, (plus.first - minus.first) / (2 * h), 1e-9) << theta;
        }
    // exp(sin - 1) less its mean: 1 - mean at the crest (theta = pi/2), e^-2 - mean in the trough,
    // so the crest stands 1 above the trough as in the notes.
    const double crest = step04::wave_shape(Shape::ExpSine, 1.5707963267948966).value;
    const double trough = step04::wave_shape(Shape::ExpSine, -1.5707963267948966).value;
    EXPECT_NEAR(crest, 1.0 - step04::kExpSineMean, 1e-15);
    EXPECT_NEAR(crest - trough, 1.0 - std::exp(-2.0), 1e-15);
}

TEST(Step04Shape, EveryShapeHasZeroMeanSoTheSeaRestsAtZero) {
    // Outside the code: the mean of exp(sin - 1) is e^-1 I0(1) (I0 from its power series
    // sum (1/4)^k / k!^2), and a periodic wave of zero mean leaves the sea's level at y = 0.
    double i0 = 0, term = 1;
    for (int k = 0; k < 30; ++k) i0 += term, term *= 0.25 / double((k + 1) * (k + 1));
    EXPECT_NEAR(step04::kExpSineMean, i0 / std::exp(1.0), 1e-15);
    // ((1 + sin) / 2)^3 (exercise 4) has its mean taken out too: the rule holds power_sine_shape's.
    for (Shape shape : {Shape::Sine, Shape::ExpSine, Shape::PowerSine}) {
        const int samples = 4096;  // the trapezoid rule is spectrally exact for periodic functions
        double mean = 0;
        for (int i = 0; i < samples; ++i) mean += step04::wave_shape(shape, step04::kTwoPi * i / samples).value;
        EXPECT_NEAR(mean / samples, 0.0, 1e-14) << int(shape);
    }
    // The whole default fBm, averaged over a large area (many wavelengths of every wave): ~0, not
    // the ~4 m of sum a_i e^-1 I0(1) it had before the mean was taken out.
    step04::CascadeSettings s;
    const auto cascades = step04::make_cascades(s, 2, 0.37);
    double mean = 0, amplitude_sum = 0;
    for (const auto& c : cascades)
        for (const auto& w : c.waves) amplitude_sum += w.amplitude;
    const int n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) mean += step04::height_gradient(cascades, Shape::ExpSine, 0.0, i * 2.03, j * 1.97, 0).height;
    mean /= double(n) * n;
    EXPECT_LT(std::abs(mean), 0.02 * amplitude_sum) << "mean level " << mean << " m, sum of amplitudes " << amplitude_sum;
}

TEST(Step04Fbm, CrestsTravelAlongTheirDirection) {
    // One exp-sine wave: its crest (the maximum along d) moves along +d at phi / w.
    step04::CascadeSettings s;
    s.wave_count = 1;
    s.base_wavelength = 10;
    const auto waves = step04::fbm_waves(s);
    const auto& w = waves[0];
    const double speed = w.phase_rate / w.wavenumber;
    auto crest_at = [&](double t) {
        double best_s = 0, best_h = -1e9;
        for (double along = -5; along < 5; along += 1e-3) {
            const double h = step04::cascade_height_gradient(waves, Shape::ExpSine, 0.0, along * w.dx, along * w.dz, t).height;
            if (h > best_h) best_h = h, best_s = along;
        }
        return best_s;
    };
    // The search spans one wavelength, so the crest may wrap: compare modulo the wavelength.
    for (double t : {0.25, 0.5}) {
        const double moved = crest_at(t) - crest_at(0);
        EXPECT_NEAR(std::remainder(moved - speed * t, 10.0), 0.0, 2e-3) << "t = " << t;
        EXPECT_GT(std::abs(std::remainder(moved + speed * t, 10.0)), 0.5) << "not the notes' -d";
    }
}

TEST(Step04Fbm, AmplitudeAndFrequencySeries) {
    step04::CascadeSettings s;
    s.wave_count = 64;
    s.base_wavelength = 25;
    s.base_amplitude = 0.9;
    s.speed_scale = 1.5;
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
        expected += w.amplitude * (std::exp(std::sin((w.dx * x + w.dz * z) * w.wavenumber - w.phase_rate * t) - 1) -
                                   step04::kExpSineMean);
    EXPECT_NEAR(step04::cascade_height_gradient(waves, Shape::ExpSine, 0.0, x, z, t).height, expected, 1e-12);
}

TEST(Step04Fbm, WarpedGradientIsExact) {
    // The chain rule through the warp against central differences of the warped height.
    step04::CascadeSettings s;
    s.wave_count = 32;
    const auto cascades = step04::make_cascades(s, 2, 0.37);
    const double h = 1e-5;
    for (Shape shape : {Shape::Sine, Shape::ExpSine, Shape::PowerSine})
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

// The shapes compare seas of the same height: found by search over a period, each spans
// 1 - e^-2 = 0.8647 from crest to trough (an unscaled sine would span 2, 2.3 times more).
TEST(Step04Shape, BothShapesSpanTheSameCrestToTroughHeight) {
    for (Shape shape : {Shape::Sine, Shape::ExpSine, Shape::PowerSine}) {
        double low = 1e9, high = -1e9;
        for (int i = 0; i < 100000; ++i) {
            const double v = step04::wave_shape(shape, 2 * M_PI * i / 100000).value;
            low = std::min(low, v);
            high = std::max(high, v);
        }
        EXPECT_NEAR(high - low, 1 - std::exp(-2.0), 1e-9) << int(shape);
    }
}

// A camera drag (or any parameter outside the waves: the light, the grid, the shape, the warp)
// rebuilds no waves; each wave parameter does. The registry's own counter moves for every change,
// which is why step04 no longer watches it (it rebuilt its cascades on every frame of a drag).
TEST(Step04Params, OnlyWaveParametersRebuildTheWaves) {
    ocean::ParamRegistry registry;
    step04::FbmParams fbm;
    fbm.declare(registry);
    ocean::Camera camera;  // declared as App::use_camera declares it, then dragged and scrolled
    camera.declare_params(registry, ocean::camera_view("deck"));
    const unsigned made_for = fbm.changes.value;
    ocean::CameraInput drag;
    drag.drag = {40.0f, -12.0f};
    drag.scroll = 2.0f;
    drag.move = {1.0f, 0.0f, 1.0f};
    for (int frame = 0; frame < 10; ++frame) camera.apply(drag, 1.0f / 60.0f);
    EXPECT_EQ(fbm.changes.value, made_for) << "a camera drag rebuilt the waves";
    for (const char* other : {"camera_yaw=42", "camera_mode=fly", "warp=2", "shape=sine"}) {
        const std::string text = other;
        const auto eq = text.find('=');
        ASSERT_FALSE(registry.set(text.substr(0, eq), text.substr(eq + 1)).has_value()) << other;
        EXPECT_EQ(fbm.changes.value, made_for) << other << " rebuilt the waves";
    }
    for (const char* wave : {"wave_count=12", "base_wavelength=30", "amplitude=2", "gain=0.7", "lacunarity=1.3",
                             "speed_scale=2", "seed=9", "cascade_count=3", "cascade_ratio=0.5"}) {
        const unsigned before = fbm.changes.value;
        const std::string text = wave;
        const auto eq = text.find('=');
        ASSERT_FALSE(registry.set(text.substr(0, eq), text.substr(eq + 1)).has_value()) << wave;
        EXPECT_GT(fbm.changes.value, before) << wave << " did not rebuild the waves";
    }
}
