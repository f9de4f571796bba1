// The slope moments step05 keeps for step06's roughness (LEAN mapping): level 0 holds the CPU
// reference's slopes squared, and the mip chain keeps the law of total variance: at every level,
// the mean of (E[s^2] - E[s]^2) over the texels plus the variance of the mean slopes is the
// variance of the full-resolution slopes. What the mips average away is exactly what the
// roughness gets back.
#include "step05_fft/gpu_ocean.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <cmath>

namespace {

using namespace step05;

struct SlopeMoments : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

std::vector<float> read_level(GLuint texture, int level, int size) {
    std::vector<float> texels(std::size_t(size) * size * 4);
    glGetTextureSubImage(texture, level, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

TEST_F(SlopeMoments, LevelZeroHoldsTheSlopesSquared) {
    SpectrumParams p;
    p.resolution = 64;
    const InitialSpectrum s = initial_spectrum(p);
    GpuOcean ocean(cache.factory());
    ocean.set_spectra({&s});
    ocean.simulate(3.0, Backend::GpuFft, 1.0f);
    const OceanMaps reference = simulate_cpu(s, 3.0);
    const auto moments = read_level(ocean.slope_moments_texture(), 0, 64);
    double worst = 0, largest = 0;
    for (std::size_t i = 0; i < 64 * 64; ++i) {
        const double sx = reference[SlopeX][i], sz = reference[SlopeZ][i];
        const double expected[3] = {sx * sx, sz * sz, sx * sz};
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(moments[4 * i + std::size_t(c)] - expected[c]));
            largest = std::max(largest, std::abs(expected[c]));
        }
    }
    EXPECT_LT(worst / largest, 1e-4);
}

TEST_F(SlopeMoments, MipsKeepTheTotalVariance) {
    SpectrumParams p;
    p.resolution = 64;
    p.wind_speed = 14;
    const InitialSpectrum s = initial_spectrum(p);
    GpuOcean ocean(cache.factory());
    ocean.set_spectra({&s});
    ocean.simulate(3.0, Backend::GpuFft, 1.0f);
    // The full-resolution variance of sx + sz (the tile's mean slope is 0).
    const auto slopes0 = read_level(ocean.slopes_texture(), 0, 64);
    double total = 0;
    for (std::size_t i = 0; i < 64 * 64; ++i)
        total += (slopes0[4 * i] * slopes0[4 * i] + slopes0[4 * i + 1] * slopes0[4 * i + 1]) / (64.0 * 64.0);
    for (int level = 1; level <= 6; ++level) {
        const int size = 64 >> level;
        const auto slopes = read_level(ocean.slopes_texture(), level, size);
        const auto moments = read_level(ocean.slope_moments_texture(), level, size);
        double within = 0, between = 0;
        for (std::size_t i = 0; i < std::size_t(size) * size; ++i) {
            const double sx = slopes[4 * i], sz = slopes[4 * i + 1];
            within += (moments[4 * i] - sx * sx + moments[4 * i + 1] - sz * sz) / (size * size);
            between += (sx * sx + sz * sz) / (size * size);
        }
        EXPECT_NEAR((within + between) / total, 1.0, 1e-4) << "level " << level;
        if (level == 6) {  // one texel: all of the variance is unresolved, none is left in the mean
            EXPECT_NEAR(within / total, 1.0, 1e-4);
            std::printf("slope variance %.6f: the 1x1 mip's unresolved part %.6f, expected from the spectrum %.6f\n",
                        total, within, resolved_slope_variance(p));
        }
    }
    // And the realized variance is the spectrum's (one sea: within its luck of a few percent).
    EXPECT_NEAR(total / resolved_slope_variance(p), 1.0, 0.1);
}

}  // namespace
