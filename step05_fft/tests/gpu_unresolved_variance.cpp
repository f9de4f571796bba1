// What a mip level of the slope map averages away, predicted from the spectrum (step05's
// unresolved_slope_variance_by_level: the box filter's response cos(k d 2^j / 2) per level), against
// what the GPU's mipmaps actually keep: at level l the mean over texels of the mean slope squared
// is the variance left, so the full-resolution variance less it is what a shader that reads the
// mipmaps must add back as roughness. One sea's mipmaps against the expectation: within its luck.
#include "step05_fft/ocean_simulation.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <cmath>
#include <cstdio>

namespace {

using namespace step05;

struct UnresolvedVariance : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

// The mean of sx^2 + sz^2 over level `level` of the slope map (size x size texels).
double kept_variance(GLuint texture, int level, int size) {
    std::vector<float> texels(std::size_t(size) * size * 4);
    glGetTextureSubImage(texture, level, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(texels.size() * sizeof(float)), texels.data());
    double sum = 0;
    for (std::size_t i = 0; i < std::size_t(size) * size; ++i)
        sum += double(texels[4 * i]) * texels[4 * i] + double(texels[4 * i + 1]) * texels[4 * i + 1];
    return sum / (double(size) * size);
}

TEST_F(UnresolvedVariance, MipmapsAverageAwayWhatTheSpectrumPredicts) {
    SpectrumParams p;
    p.resolution = 128;
    p.wind_speed = 14;
    const InitialSpectrum s = initial_spectrum(p);
    OceanSimulation ocean(cache.factory());
    ocean.set_spectra({&s});
    ocean.simulate(3.0, Backend::GpuFft, 1.0f);
    const std::vector<double> predicted = unresolved_slope_variance_by_level(p);
    ASSERT_EQ(predicted.size(), 8u);
    EXPECT_EQ(predicted[0], 0.0);
    EXPECT_NEAR(predicted.back() / resolved_slope_variance(p), 1.0, 1e-9);  // 1 x 1: all of it
    const double total = kept_variance(ocean.slopes_texture(), 0, 128);
    std::printf("level  texels  unresolved: measured / expected (fraction of the total)\n");
    for (int level = 1; level < 8; ++level) {
        EXPECT_GE(predicted[std::size_t(level)], predicted[std::size_t(level - 1)]);
        const int size = 128 >> level;
        const double measured = total - kept_variance(ocean.slopes_texture(), level, size);
        const double expected = predicted[std::size_t(level)];
        std::printf("%5d %7d  %.6f / %.6f (%.3f / %.3f)\n", level, size, measured, expected, measured / total,
                    expected / predicted.back());
        // As fractions of the total (one sea's luck in its overall energy cancels): within 0.03.
        EXPECT_NEAR(measured / total, expected / predicted.back(), 0.03) << "level " << level;
    }
    // And the realised variance is the spectrum's (one sea: within its luck of a few percent).
    EXPECT_NEAR(total / resolved_slope_variance(p), 1.0, 0.1);
}

}  // namespace
