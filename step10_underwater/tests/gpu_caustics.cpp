// The caustics on the GPU (caustics.vert/.frag, through the Caustics part the program uses), held
// to the CPU's ray tracing (caustics_reference.hpp) and to the closed forms it is itself held to:
// the light conserved, and the crests focusing at a lens's focal depth.
//
// The sea is one wave through step05's simulation and step06's cascades, as the program reads
// them: h = a cos(k . x), a = 5 cm, 1.98 m long, with no choppiness (the reference bends no water
// sideways). The sun is overhead, so the reference's 1D sea along k is the same sea. The wave is
// the tile's mode (8, 1), 7.1 degrees off the x axis: were it along x, every row of texels would
// meet the same thin triangles at the same place across it, and a triangle thinner than a texel
// adds its light to the one texel whose centre it covers (right on average over many offsets,
// not in one): slanted, the rows meet them at every offset. The caustic window is finer than the
// program's (16 cm texels over 32 m): 4 m, two wavelengths, at 1024 texels (3.9 mm) from 1024
// rays a side (4.9 mm apart), so that the focus is resolved: a line's binned peak lies past the
// focus by about the depth over which the folds leaving the cusp stay within one bin
// (test_optics.cpp; at 512 bins a wavelength, about 5 %).
#include "common/constants.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step10_underwater/caustics.hpp"
#include "step10_underwater/caustics_reference.hpp"
#include "step10_underwater/optics.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr int kN = 256, kModeX = 8, kModeZ = 1;
constexpr double kTile = 16;  // metres: mode (8, 1) is a 1.98 m wave, 32 texels a wavelength
constexpr int kBins = 512;    // over a wavelength: about a texel each

struct CausticsOnOneWave : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    const glm::dvec2 k = 2 * ocean::kPi / kTile * glm::dvec2(kModeX, kModeZ);
    step10::CausticSea sea;  // a = 5 cm, sun overhead; the wavenumber, |k|, is set below
    std::vector<step05::InitialSpectrum> spectra;
    std::unique_ptr<step05::OceanSimulation> ocean;
    step06::CascadeView cascades;
    step10::Caustics caustics;
    const step10::CausticWindow window{4.0f, 1024, 1024};

    void SetUp() override {
        ocean_test::GlTest::SetUp();
        sea.wavenumber = glm::length(k);
        step05::SpectrumParams calm;
        calm.resolution = kN;
        calm.patch_size = kTile;
        calm.wind_speed = 0;
        spectra.assign(4, step05::initial_spectrum(calm));
        // h0(k) = a / 2 at +k only: the evolution adds its conjugate at -k, h = a cos(k . x - omega t).
        const std::size_t mode = std::size_t(kModeZ * kN + kModeX);  // row j = kz, column i = kx
        spectra[0].h0[mode] = {sea.amplitude / 2, 0};
        ASSERT_NEAR(spectra[0].omega[mode], std::sqrt(ocean::kGravity * sea.wavenumber), 1e-9) << "the mode is k";
        std::vector<const step05::InitialSpectrum*> pointers;
        for (const auto& s : spectra) pointers.push_back(&s);
        ocean = std::make_unique<step05::OceanSimulation>(cache.factory());
        ocean->set_spectra(pointers);
        ocean->simulate(0, step05::Backend::GpuFft, 0.0f);  // t = 0: a crest at x = 0; no choppiness
        const auto sizes = step06::cascade_patch_sizes(kTile);
        for (int c = 0; c < step06::kCascades; ++c) cascades.patch_sizes[std::size_t(c)] = float(sizes[std::size_t(c)]);
    }

    // The floor at `depth`, over a flat sea's, averaged along the crests and folded into one
    // wavelength: each texel's centre to its phase k . x, in kBins bins, bin 0 starting under a
    // crest (k . x = 0).
    step10::SeabedIrradiance floor_at(double depth) {
        const bool drawn = caustics.update(
            cache.factory(), {"EXTRA_WAVES 0"},
            [this](const ocean::ShaderProgram& p) {
                cascades.upload(p);
                ocean->bind_maps(p);
            },
            window, {{0, 1, 0}, float(depth), {0, 0}});
        EXPECT_TRUE(drawn);
        const int r = window.resolution;
        std::vector<float> texels(std::size_t(r) * std::size_t(r));
        glGetTextureImage(caustics.texture(), 0, GL_RED, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
        std::vector<double> sum(kBins, 0.0), count(kBins, 0.0);
        const double texel = double(window.size) / r;
        for (int j = 0; j < r; ++j)
            for (int i = 0; i < r; ++i) {
                const glm::dvec2 at = glm::dvec2(caustics.centre()) + texel * (glm::dvec2(i, j) + 0.5 - 0.5 * r);
                const double turns = glm::dot(k, at) / (2 * ocean::kPi);
                const std::size_t bin = std::min(std::size_t((turns - std::floor(turns)) * kBins), std::size_t(kBins - 1));
                sum[bin] += texels[std::size_t(j * r + i)];
                count[bin] += 1;
            }
        for (std::size_t b = 0; b < sum.size(); ++b) sum[b] /= std::max(count[b], 1.0);
        return {sum};
    }
};

TEST_F(CausticsOnOneWave, TheFloorReceivesTheTransmittedLight) {
    // The mean over the floor is what the surface let through (the reference's mean, itself held
    // to the Fresnel transmittance averaged over the surface), within 2 %, however the light is
    // gathered: above, at and past the focus. The texture holds irradiance over a flat sea's
    // 1 - R, which the reference's includes.
    const double flat = 1 - step10::fresnel_reflectance(0, 1.0, step10::kWaterIndex);
    const double focus = step10::crest_focal_depth(sea);
    for (double depth : {0.25 * focus, 0.5 * focus, focus, 1.5 * focus}) {
        step10::CausticSea at = sea;
        at.depth = depth;
        const double reference = step10::seabed_irradiance(at).mean();
        const double gpu = floor_at(depth).mean() * flat;
        std::printf("depth %5.2f m: mean %.5f (reference %.5f, %+.2f %%)\n", depth, gpu, reference, 100 * (gpu / reference - 1));
        EXPECT_NEAR(gpu / reference, 1, 0.02) << depth << " m";
    }
}

TEST_F(CausticsOnOneWave, ThePatternIsTheReferences) {
    // Above the focus the pattern is smooth: bin by bin, the GPU's floor is the CPU's within 3 %
    // of the mean (the maps' bilinear slopes and the half floats' 0.1 % are what differ).
    const double focus = step10::crest_focal_depth(sea);
    for (double depth : {0.25 * focus, 0.5 * focus}) {
        const step10::SeabedIrradiance gpu = floor_at(depth);
        step10::CausticSea at = sea;
        at.depth = depth;
        at.bins = int(gpu.irradiance.size());
        const step10::SeabedIrradiance reference = step10::seabed_irradiance(at);
        const double flat = 1 - step10::fresnel_reflectance(0, 1.0, step10::kWaterIndex);
        double worst = 0;
        for (std::size_t i = 0; i < gpu.irradiance.size(); ++i)
            worst = std::max(worst, std::abs(gpu.irradiance[i] * flat - reference.irradiance[i]) / reference.mean());
        std::printf("depth %5.2f m: peak/mean %.3f (reference %.3f), worst bin %.2f %% of the mean\n", depth,
                    gpu.peak_over_mean(), reference.peak_over_mean(), 100 * worst);
        EXPECT_LT(worst, 0.03) << depth << " m";
    }
}

TEST_F(CausticsOnOneWave, BrightestAtTheCrestsFocalDepthAndFadingPastIt) {
    // The crests are lenses of focal depth n / ((n - 1) a k^2) = 7.98 m: the floor's brightest line
    // is found within 10 % of it, and past it the pattern evens out.
    const double focus = step10::crest_focal_depth(sea);
    std::vector<double> depths, peaks, contrasts;
    for (double d = 0.6 * focus; d < 1.41 * focus; d += 0.05 * focus) {
        const step10::SeabedIrradiance floor = floor_at(d);
        depths.push_back(d);
        peaks.push_back(floor.peak_over_mean());
        contrasts.push_back(floor.contrast());
        std::printf("depth %5.2f m (%.2f f): peak/mean %6.2f, contrast %.3f\n", d, d / focus, peaks.back(), contrasts.back());
    }
    const std::size_t brightest = std::size_t(std::max_element(peaks.begin(), peaks.end()) - peaks.begin());
    EXPECT_NEAR(depths[brightest] / focus, 1, 0.1) << "brightest at " << depths[brightest] << " m";
    EXPECT_GT(peaks[brightest], 10) << "a caustic, not a ripple";
    for (std::size_t i = brightest + 2; i < depths.size(); ++i)
        EXPECT_LT(contrasts[i], contrasts[i - 1]) << "past the focus, " << depths[i] << " m";
}

}  // namespace
