// step06 on the GPU: foam decay at two frame rates, both clocks of foam against the CPU's steps
// (on a calm sea filled with known foam, on a moving sea), the cover functions on the uploaded
// pattern, foam made by the summed surface (against the CPU reference, at mip level 0 and at whole
// levels below it) and kept in world space when the camera moves, the box mipmaps (against the 2 x
// 2 mean and glGenerateMipmap), tessellation (primitive counts against the CPU level, culling
// behind the camera), the sky cubemap (the sun's texel, an image sky, missing and corrupt files),
// the bloom chain and the tonemap pass.
#include "common/frustum.hpp"
#include "common/image.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/bloom.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/foam_pattern.hpp"
#include "step06_foam_sky/patch_grid.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sky.hpp"
#include "step06_foam_sky/tessellation.hpp"
#include "step06_foam_sky/texture_units.h"
#include "step06_foam_sky/tonemap.hpp"
#include "tests/gpu/full_screen_draw.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/one_texel_target.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

namespace {

struct Step06Gpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    ocean::ProgramFactory factory() { return cache.factory(); }
    // tests/foam_cover.frag: the renderer's cover functions at each texel of the pattern texture.
    ocean::ShaderProgram* foam_cover_program() {
        return cache("foam_cover", {"common/shaders/fullscreen.vert", "step06_foam_sky/tests/foam_cover.frag"}, {});
    }
    // A calm sea (all maps zero, J = 1) of 4 cascades at N = 64.
    std::vector<step05::InitialSpectrum> calm = std::vector<step05::InitialSpectrum>(4);
    std::unique_ptr<step05::OceanSimulation> calm_ocean() {
        step05::SpectrumParams p;
        p.resolution = 64;
        p.wind_speed = 0;
        std::vector<const step05::InitialSpectrum*> pointers;
        for (auto& s : calm) {
            s = step05::initial_spectrum(p);
            pointers.push_back(&s);
        }
        auto ocean = std::make_unique<step05::OceanSimulation>(factory());
        ocean->set_spectra(pointers);
        ocean->simulate(0, step05::Backend::GpuFft, 1);
        return ocean;
    }
};

// One texel's two clocks on the CPU: the active foam a and the foam as a whole f (foam.hpp).
struct TwoClocksCpu {
    double active, whole;
};

step06::CascadeView all_cascades(double largest = 500) {
    step06::CascadeView view;
    const auto sizes = step06::cascade_patch_sizes(largest);
    for (int c = 0; c < 4; ++c) view.patch_sizes[std::size_t(c)] = float(sizes[std::size_t(c)]);
    return view;
}

TEST_F(Step06Gpu, FoamImpulseDecaysAsExpOfRateTimesTimeAtAnyFrameRate) {
    const auto ocean = calm_ocean();
    step06::FoamSettings settings;
    settings.decay_rate = 1.3;
    for (double dt : {1.0 / 30, 1.0 / 120}) {
        step06::FoamSimulation foam(factory());
        foam.resize(64);
        foam.fill(1.0f);
        for (int i = 0; i < int(std::lround(1 / dt)); ++i)
            foam.update(ocean->maps(), all_cascades(), {0, 0}, {1, 0}, dt, settings);
        const auto values = foam.read_level(2);
        const double expected = std::exp(-1.3);
        for (float v : values) ASSERT_NEAR(v / expected, 1.0, 0.01) << "dt = " << dt;
        std::printf("foam after 1 s at dt = 1/%d: %.6f, exp(-1.3) = %.6f\n", int(std::lround(1 / dt)), values[0],
                    expected);
    }
}

// A windy sea of 4 cascades at N = 64, simulated at t, and the CPU reference maps of each.
struct WindySea {
    std::vector<step05::InitialSpectrum> spectra;
    std::vector<step05::OceanMaps> cpu;
    std::unique_ptr<step05::OceanSimulation> gpu;
};

WindySea windy_sea(ocean::ProgramFactory factory, double time, float choppiness) {
    step05::SpectrumParams shared;
    shared.resolution = 64;
    shared.patch_size = 500;
    shared.wind_speed = 14;
    WindySea sea;
    for (const auto& p : step06::cascade_spectra(shared)) sea.spectra.push_back(step05::initial_spectrum(p));
    std::vector<const step05::InitialSpectrum*> pointers;
    for (const auto& s : sea.spectra) {
        pointers.push_back(&s);
        sea.cpu.push_back(step05::simulate_cpu(s, time));
    }
    sea.gpu = std::make_unique<step05::OceanSimulation>(std::move(factory));
    sea.gpu->set_spectra(pointers);
    sea.gpu->simulate(time, step05::Backend::GpuFft, choppiness);
    return sea;
}

// Bilinear interpolation of an n x n grid that wraps, at grid coordinates (u, v) (texel (i, j) at
// (i, j)); texel(i, j) reads the grid. weight_bits > 0 truncates the weights to that many
// fractional bits, as a GPU's texture unit may.
template <typename Texel>
double bilinear_wrapped(int n, double u, double v, int weight_bits, const Texel& texel) {
    const double fu = std::floor(u), fv = std::floor(v);
    const double steps = std::ldexp(1.0, weight_bits);
    const double a = weight_bits > 0 ? std::floor((u - fu) * steps) / steps : u - fu;
    const double b = weight_bits > 0 ? std::floor((v - fv) * steps) / steps : v - fv;
    auto at = [&](double i, double j) { return texel(((int(i) % n) + n) % n, ((int(j) % n) + n) % n); };
    return (1 - a) * (1 - b) * at(fu, fv) + a * (1 - b) * at(fu + 1, fv) + (1 - a) * b * at(fu, fv + 1) +
           a * b * at(fu + 1, fv + 1);
}

// A field of the CPU maps at world position (x, z), bilinear between the samples x_i = i L / N
// (the convention the shaders' half-texel offset keeps).
double bilinear(const step05::OceanMaps& maps, step05::Field field, double x, double z, int weight_bits = 0) {
    const int n = maps.n;
    return bilinear_wrapped(n, x / maps.patch_size * n, z / maps.patch_size * n, weight_bits,
                            [&](int i, int j) { return double(maps[field][std::size_t(j) * std::size_t(n) + std::size_t(i)]); });
}

TEST_F(Step06Gpu, FoamComesFromTheJacobianOfTheSummedCascades) {
    // Cascades 0 and 1 only: at level 0 (64 m over 64 texels, 1 m each) both are magnified
    // (their texels are 7.8 m and 2.1 m), so the GPU reads mip level 0 and the CPU reference is a
    // plain bilinear interpolation of the FFTW maps. The first update starts every texel at the
    // steady state of its J, foam_steady_state(J), which is then held to the CPU in double.
    const float choppiness = 1.6f;
    const WindySea sea = windy_sea(factory(), 7.0, choppiness);
    step06::CascadeView view = all_cascades();
    view.enabled = {true, true, false, false};
    step06::FoamSimulation foam(factory());
    foam.resize(64);
    step06::FoamSettings settings;
    settings.injection = 3;
    settings.threshold = 0.9;  // foam on more texels than the default 0.7 gives two cascades
    const glm::dvec2 eye(37.0, -12.0);
    foam.update(sea.gpu->maps(), view, eye, {0, 1}, 0.0, settings);
    const auto values = foam.read_level(0);
    const step06::FoamWindow& window = foam.window(0);
    double worst = 0, foamy = 0, weight_gap = 0;
    int folded = 0;
    const auto foam_at = [&](const glm::dvec2& p, int weight_bits) {
        double xx = 1, zz = 1, xz = 0;
        for (int c = 0; c < 2; ++c) {
            xx += choppiness * bilinear(sea.cpu[std::size_t(c)], step05::DDxDx, p.x, p.y, weight_bits);
            zz += choppiness * bilinear(sea.cpu[std::size_t(c)], step05::DDzDz, p.x, p.y, weight_bits);
            xz += choppiness * bilinear(sea.cpu[std::size_t(c)], step05::DDxDz, p.x, p.y, weight_bits);
        }
        const double jacobian = xx * zz - xz * xz;
        return std::pair(jacobian, step06::foam_steady_state(jacobian, settings));
    };
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const glm::dvec2 p = window.cell_centre(i, j);
            const auto [jacobian, expected] = foam_at(p, 0);
            worst = std::max(worst, std::abs(values[std::size_t(j) * 64 + i] - expected));
            weight_gap = std::max(weight_gap, std::abs(foam_at(p, 8).second - expected));
            foamy = std::max(foamy, expected);
            folded += jacobian < settings.threshold;
        }
    std::printf("foam from the summed Jacobian: %d of 4096 texels below the threshold, worst |GPU - CPU| = %.2e "
                "(8-bit filter weights could cost %.2e)\n",
                folded, worst, weight_gap);
    ASSERT_GT(folded, 20) << "the test needs some foam to compare";
    // GPUs filter with 8 fractional bits of weight (D3D11's minimum; an H100 errs by 2.7e-3 here),
    // llvmpipe in float (1e-6). The limit: what truncating the weights to 8 bits costs, doubled for
    // rounding the coordinate first. Slips cost far more: 0.06 for a 5 % error in one choppy
    // derivative, 0.22 for J = xx zz + xz^2.
    EXPECT_LT(worst, 2 * weight_gap + 1e-5);
}

// One field of one cascade's CPU maps at mip level k, as glGenerateMipmap makes it (each texel the
// mean of 2^k x 2^k texels of level 0), sampled bilinearly where GL samples level k: map_uv's half
// texel of level 0 puts x at level-k texel (x / L + 0.5 / N) N_k - 0.5. weight_bits as bilinear's.
struct MipField {
    int n0, n;
    double patch_size;
    std::vector<double> texels;
    MipField(const step05::OceanMaps& maps, step05::Field field, int level)
        : n0(maps.n), n(maps.n >> level), patch_size(maps.patch_size), texels(std::size_t(n) * std::size_t(n)) {
        const int box = 1 << level;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                double sum = 0;
                for (int b = 0; b < box; ++b)
                    for (int a = 0; a < box; ++a) sum += maps[field][std::size_t(j * box + b) * std::size_t(n0) + std::size_t(i * box + a)];
                texels[std::size_t(j) * std::size_t(n) + std::size_t(i)] = sum / (box * box);
            }
    }
    double at(double x, double z, int weight_bits = 0) const {
        return bilinear_wrapped(n, (x / patch_size + 0.5 / n0) * n - 0.5, (z / patch_size + 0.5 / n0) * n - 0.5, weight_bits,
                                [&](int i, int j) { return texels[std::size_t(j) * std::size_t(n) + std::size_t(i)]; });
    }
};

TEST_F(Step06Gpu, FoamReadsEachCascadeAtTheWholeMipLevelNearestItsTexel) {
    // Clipmap level 1 at N = 64 has 4 m texels, but every level reads the cascades with the finest
    // level's footprint (1 m at N = 64: foam.frag says why), at its texel's centre. Cascade 0
    // (7.8 m texels) is magnified; the others are minified, each between two mip levels: 1 m over
    // 2.1 m, 0.64 m and 0.18 m. surface_at reads the nearest whole level of each; the reference
    // box-filters the FFTW maps to those levels and samples them as GL does. A blend of the two
    // levels around each footprint, what trilinear filtering reads, must fall far outside the
    // tolerance, or this test could not tell the two apart.
    const float choppiness = 1.6f;
    const WindySea sea = windy_sea(factory(), 7.0, choppiness);
    step06::FoamSimulation foam(factory());
    foam.resize(64);
    step06::FoamSettings settings;
    settings.injection = 3;
    settings.threshold = 1.0;  // foam wherever J < 1: many texels to compare
    foam.update(sea.gpu->maps(), all_cascades(), {37.0, -12.0}, {0, 1}, 0.0, settings);
    const auto values = foam.read_level(1);
    const step06::FoamWindow& window = foam.window(1);
    ASSERT_NEAR(window.texel_size, 4.0, 1e-12);
    // Each cascade's levels: below (floor of the footprint's level), above, the blend's weight,
    // and the nearest whole level (halves up, as the shader). None is skipped: the finest tile,
    // 11.5 m, is over two texels.
    const std::array<step05::Field, 3> fields{step05::DDxDx, step05::DDzDz, step05::DDxDz};
    struct CascadeLevels {
        double level;  // of the footprint, fractional
        std::vector<MipField> below, above, nearest;
        double blend;
    };
    std::vector<CascadeLevels> cascades;
    for (const auto& maps : sea.cpu) {
        ASSERT_LT(window.texel_size, 0.5 * maps.patch_size);
        const double footprint = foam.window(0).texel_size;  // the finest level's, on every level
        const double level = std::max(0.0, std::log2(footprint * maps.n / maps.patch_size));
        const int below = int(std::floor(level)), nearest = int(std::floor(level + 0.5));
        CascadeLevels c;
        c.level = level;
        c.blend = level - below;
        for (const auto f : fields) {
            c.below.emplace_back(maps, f, below);
            c.above.emplace_back(maps, f, below + 1);
            c.nearest.emplace_back(maps, f, nearest);
        }
        cascades.push_back(std::move(c));
    }
    // J from the three summed derivatives, then the steady state foam.update starts every texel at.
    const auto foam_from = [&](const glm::dvec2& p, auto&& field_at) {
        double xx = 1, zz = 1, xz = 0;
        for (const auto& c : cascades) {
            xx += choppiness * field_at(c, 0, p);
            zz += choppiness * field_at(c, 1, p);
            xz += choppiness * field_at(c, 2, p);
        }
        const double jacobian = xx * zz - xz * xz;
        return std::pair(jacobian, step06::foam_steady_state(jacobian, settings));
    };
    double worst = 0, weight_gap = 0, blend_gap = 0;
    int folded = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const glm::dvec2 p = window.cell_centre(i, j);
            const auto [jacobian, expected] = foam_from(p, [](const CascadeLevels& c, int f, const glm::dvec2& q) {
                return c.nearest[std::size_t(f)].at(q.x, q.y);
            });
            const double truncated = foam_from(p, [](const CascadeLevels& c, int f, const glm::dvec2& q) {
                return c.nearest[std::size_t(f)].at(q.x, q.y, 8);
            }).second;
            const double blended = foam_from(p, [](const CascadeLevels& c, int f, const glm::dvec2& q) {
                return (1 - c.blend) * c.below[std::size_t(f)].at(q.x, q.y) + c.blend * c.above[std::size_t(f)].at(q.x, q.y);
            }).second;
            worst = std::max(worst, std::abs(values[std::size_t(j) * 64 + i] - expected));
            weight_gap = std::max(weight_gap, std::abs(truncated - expected));
            blend_gap = std::max(blend_gap, std::abs(blended - expected));
            folded += jacobian < settings.threshold;
        }
    const double tolerance = 2 * weight_gap + 1e-5;  // as FoamComesFromTheJacobianOfTheSummedCascades
    std::printf("foam at clipmap level 1 (cascades at mip levels %.2f %.2f %.2f %.2f, read at the nearest whole): "
                "%d of 4096 texels below the threshold, worst |GPU - CPU| = %.2e (tolerance %.2e); the blend of "
                "two levels would differ by up to %.2e\n",
                cascades[0].level, cascades[1].level, cascades[2].level, cascades[3].level, folded, worst, tolerance, blend_gap);
    ASSERT_GT(folded, 20) << "the test needs some foam to compare";
    EXPECT_GT(blend_gap, 10 * tolerance) << "whole levels and blended ones must be told apart";
    EXPECT_LT(worst, tolerance);
}

// The same foam at 6 and at 60 frames a second, texel by texel, on a windy sea held still (J
// fixed: each step is exact then, so only float rounding separates the two frame rates), both
// clocks: the active foam a and the foam as a whole f. Each run starts from no foam and grows it
// for 1 s. The explicit step it replaced (f e^{-r dt} + q dt) made more foam at 6 frames a second
// (16 % in the CPU test), far outside the limit.
TEST_F(Step06Gpu, TheSameFoamAtSixAndSixtyFramesASecond) {
    const WindySea sea = windy_sea(factory(), 7.0, 1.6f);
    step06::FoamSettings settings;
    settings.injection = 1.5;  // below the clamp on most foamy texels: the clamp would hide a slip
    settings.threshold = 0.9;
    // Level 0's (a, f) after 1 s at `fps`.
    auto grown = [&](int fps) {
        step06::FoamSimulation foam(factory());
        foam.resize(64);
        foam.fill(0.0f);
        for (int frame = 0; frame < fps; ++frame)
            foam.update(sea.gpu->maps(), all_cascades(), {37.0, -12.0}, {0, 1}, 1.0 / fps, settings);
        return std::pair{foam.read_level(0), foam.read_whole(0)};
    };
    const auto at6 = grown(6), at60 = grown(60);
    for (bool whole : {false, true}) {
        const std::vector<float>& six = whole ? at6.second : at6.first;
        const std::vector<float>& sixty = whole ? at60.second : at60.first;
        double worst = 0, total6 = 0, total60 = 0;
        for (std::size_t i = 0; i < six.size(); ++i) {
            worst = std::max(worst, double(std::abs(six[i] - sixty[i])));
            total6 += six[i];
            total60 += sixty[i];
        }
        const char* kind = whole ? "foam as a whole" : "active foam";
        std::printf("%s after 1 s: %.4f (6 fps) and %.4f (60 fps) summed over its level, worst texel %.2e\n", kind,
                    total6, total60, worst);
        ASSERT_GT(total60, 10.0) << "the test needs " << kind << " to compare";
        EXPECT_NEAR(total6 / total60, 1.0, 1e-4) << kind;
        EXPECT_LT(worst, 1e-4) << kind;
    }
}

// The settings as the shader is given them (floats), so that the CPU reference in double differs
// from the GPU by the GPU's arithmetic only.
step06::FoamSettings as_floats(step06::FoamSettings s) {
    for (double* v : {&s.threshold, &s.injection, &s.decay_rate, &s.residual_decay}) *v = double(float(*v));
    return s;
}

// One frame of both clocks on the CPU (foam.hpp's foam_step and whole_foam_step).
TwoClocksCpu step_both(TwoClocksCpu x, double jacobian, double dt, const step06::FoamSettings& s) {
    return {step06::foam_step(x.active, jacobian, dt, s), step06::whole_foam_step(x.whole, jacobian, dt, s)};
}

// foam.frag's two clocks against foam.hpp's, on a sea where every term is known: the calm sea
// (J = 1 at every texel), each clipmap level filled with its own (a, f), then 4 frames of 0.25 s.
// A threshold above 1 makes q constant: J = 1 against thresholds of 0.72 (no injection: both only
// decay), 1.25 (q = 4 > r_a: a and f reach 1 in the first frame and are held there) and 1.0625
// (q = 0.125: a falls towards q / r_a, f rises towards its clamp), and with r_b = r_a (the
// channels one). The GPU works in float, with exp good to a few ulps: the limit is 1e-5
// relative, about 100 ulps.
TEST_F(Step06Gpu, BothClocksAreTheCpuStepsOnACalmSea) {
    const auto ocean = calm_ocean();
    const int n = 64;
    const std::array<glm::vec2, step06::kFoamLevels> starts{glm::vec2(0.2f, 0.5f), glm::vec2(0.6f, 0.9f),
                                                            glm::vec2(1.0f, 1.0f)};
    struct Case {
        const char* name;
        double threshold, injection, residual_decay;
    };
    double worst_overall = 0;
    for (const Case& c : {Case{"no injection", 0.72, 16, 0.1}, Case{"q = 4, both reach 1", 1.25, 16, 0.1},
                          Case{"q = 0.125", 1.0625, 2, 0.1}, Case{"q = 0.125, r_b = r_a", 1.0625, 2, 2.0}}) {
        step06::FoamSettings settings;
        settings.threshold = c.threshold;
        settings.injection = c.injection;
        settings.residual_decay = c.residual_decay;
        settings = as_floats(settings);
        step06::FoamSimulation foam(factory());
        foam.resize(n);
        foam.fill(0.0f);  // no warm start: the levels hold what they are given
        for (int level = 0; level < step06::kFoamLevels; ++level)
            glClearTexSubImage(foam.texture(), 0, 0, 0, level, n, n, 1, GL_RG, GL_FLOAT, &starts[std::size_t(level)]);
        double worst = 0;
        for (int frame = 1; frame <= 4; ++frame) {
            foam.update(ocean->maps(), all_cascades(), {0, 0}, {1, 0}, 0.25, settings);
            for (int level = 0; level < step06::kFoamLevels; ++level) {
                TwoClocksCpu expected{starts[std::size_t(level)].x, starts[std::size_t(level)].y};
                for (int k = 0; k < frame; ++k) expected = step_both(expected, 1.0, 0.25, settings);
                const auto active = foam.read_level(level), whole = foam.read_whole(level);
                for (std::size_t i = 0; i < active.size(); ++i)
                    worst = std::max({worst, std::abs(active[i] / expected.active - 1), std::abs(whole[i] / expected.whole - 1)});
                if (frame == 4)
                    std::printf("%-22s level %d after 1 s: (a, f) (%.6f, %.6f), CPU (%.6f, %.6f)\n", c.name, level,
                                double(active[0]), double(whole[0]), expected.active, expected.whole);
            }
        }
        std::printf("%-22s worst |GPU / CPU - 1| over 4 frames and 3 levels: %.2e\n", c.name, worst);
        EXPECT_LT(worst, 1e-5) << c.name;
        worst_overall = std::max(worst_overall, worst);
    }
    std::printf("both clocks on a calm sea: worst %.2e (limit 1e-5)\n", worst_overall);
}

// The same on a windy sea that moves: level 0 (1 m texels) warm-started at t = 7 s
// (foam_steady_state and whole_foam_steady_state of each texel's J), then 4 frames of 0.25 s, the
// sea simulated to each frame's end, against the CPU steps fed with each texel's J from the FFTW
// maps (cascades 0 and 1, magnified at level 0, as FoamComesFromTheJacobianOfTheSummedCascades).
// The limit is that test's (what 8-bit filter weights would cost, doubled, here through the whole
// run, for each clock) plus the calm sea's float limit, so the step's formula is held to the calm
// sea's test; this one holds the wiring: J into both clocks, the channels, the warm start. The
// whole foam warm-started at the active rate (a's steady state) must fall outside the limit on
// many texels.
TEST_F(Step06Gpu, BothClocksFollowTheCpuOnAMovingSea) {
    const float choppiness = 1.6f;
    const WindySea sea = windy_sea(factory(), 7.0, choppiness);
    step06::CascadeView view = all_cascades();
    view.enabled = {true, true, false, false};
    step06::FoamSettings settings;
    settings.injection = 3;
    settings.threshold = 0.9;  // foam on more texels than the default gives two cascades
    settings = as_floats(settings);
    step06::FoamSimulation foam(factory());
    foam.resize(64);
    const glm::dvec2 eye(37.0, -12.0);
    foam.update(sea.gpu->maps(), view, eye, {0, 1}, 0.0, settings);  // the warm start
    const step06::FoamWindow window = foam.window(0);
    // Each texel's J from the CPU maps at time t, with the filter's weights exact or truncated to 8 bits.
    const auto jacobians = [&](double t, int weight_bits) {
        std::vector<step05::OceanMaps> maps;
        for (int c = 0; c < 2; ++c) maps.push_back(step05::simulate_cpu(sea.spectra[std::size_t(c)], t));
        std::vector<double> j(64 * 64);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const glm::dvec2 p = window.cell_centre(x, y);
                double xx = 1, zz = 1, xz = 0;
                for (const auto& m : maps) {
                    xx += choppiness * bilinear(m, step05::DDxDx, p.x, p.y, weight_bits);
                    zz += choppiness * bilinear(m, step05::DDzDz, p.x, p.y, weight_bits);
                    xz += choppiness * bilinear(m, step05::DDxDz, p.x, p.y, weight_bits);
                }
                j[std::size_t(y) * 64 + x] = xx * zz - xz * xz;
            }
        return j;
    };
    // The CPU's run, from the warm start at t = 7 s to the end of the last frame.
    // wrong_warm_start: f warm-started at a's steady state (to show what the limit lets through).
    const auto cpu_run = [&](int frames, int weight_bits, bool wrong_warm_start = false) {
        std::vector<TwoClocksCpu> x;
        for (double j : jacobians(7.0, weight_bits)) {
            const double active = step06::foam_steady_state(j, settings);
            x.push_back({active, wrong_warm_start ? active : step06::whole_foam_steady_state(j, settings)});
        }
        for (int frame = 1; frame <= frames; ++frame) {
            const std::vector<double> j = jacobians(7.0 + 0.25 * frame, weight_bits);
            for (std::size_t i = 0; i < x.size(); ++i) x[i] = step_both(x[i], j[i], 0.25, settings);
        }
        return x;
    };
    for (int frame = 1; frame <= 4; ++frame) {
        sea.gpu->simulate(7.0 + 0.25 * frame, step05::Backend::GpuFft, choppiness);
        foam.update(sea.gpu->maps(), view, eye, {0, 1}, 0.25, settings);
    }
    ASSERT_EQ(foam.window(0).origin, window.origin) << "the window must not move";
    const auto active = foam.read_level(0), whole = foam.read_whole(0);
    const std::vector<TwoClocksCpu> exact = cpu_run(4, 0), truncated = cpu_run(4, 8), wrong = cpu_run(4, 0, true);
    double worst_active = 0, worst_whole = 0, gap_active = 0, gap_whole = 0, most_residual = 0;
    int foamy = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        worst_active = std::max(worst_active, std::abs(active[i] - exact[i].active));
        worst_whole = std::max(worst_whole, std::abs(whole[i] - exact[i].whole));
        gap_active = std::max(gap_active, std::abs(truncated[i].active - exact[i].active));
        gap_whole = std::max(gap_whole, std::abs(truncated[i].whole - exact[i].whole));
        const double residual = step06::residual_foam(exact[i].active, exact[i].whole);
        most_residual = std::max(most_residual, residual);
        foamy += residual > 0.05;
    }
    // A limit for each clock: f's is wider, as it moves 1 / r_b with q where a moves 1 / r_a.
    const double tolerance_active = 2 * gap_active + 1e-5, tolerance_whole = 2 * gap_whole + 1e-5;
    int wrong_outside = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) wrong_outside += std::abs(wrong[i].whole - exact[i].whole) > tolerance_whole;
    std::printf("a moving sea, level 0 after 1 s: %d of 4096 texels with residual foam f - a over 0.05 (up to %.3f); "
                "worst |GPU - CPU| a %.2e (tolerance %.2e), f %.2e (tolerance %.2e); f warm-started at a's steady "
                "state: %d texels outside\n",
                foamy, most_residual, worst_active, tolerance_active, worst_whole, tolerance_whole, wrong_outside);
    ASSERT_GT(foamy, 20) << "the test needs residual foam to compare";
    EXPECT_GT(wrong_outside, 100) << "the limit must not let a wrong warm start through";
    EXPECT_LT(worst_active, tolerance_active);
    EXPECT_LT(worst_whole, tolerance_whole);
}

// The renderer's cover functions (GLSL, through foam_cover.frag) against foam_pattern.hpp's, texel
// by texel of the uploaded pattern texture (8 bits: the CPU is given the same quantised cells r and
// noise g): net_cover with the active and the residual holes, residual_cover, streak_thickness
// (gathered foam up to 0.5: three times it, clamped; the noise as the breaks) and streak_gathered (the cells and the noise
// as the foam near and far upwind), at a few amounts.
TEST_F(Step06Gpu, FoamCoverMatchesTheCpuOnTheUploadedPattern) {
    step06::FoamSimulation foam(factory());
    ocean::ShaderProgram* program = foam_cover_program();
    ASSERT_NE(program, nullptr);
    const step06::FoamPatternSettings settings;
    const int n = settings.size;
    const std::vector<std::uint8_t> cells = step06::to_r8(step06::foam_pattern(settings)),
                                    noise = step06::to_r8(step06::foam_noise(settings));
    struct Case {
        int function;  // foam_cover.frag's u_function: 0 net_cover, 1 residual_cover, 2 streak_thickness, 5 streak_gathered
        float holes, amount;
    };
    const float active = float(step06::kActiveHoles), residual = float(step06::kResidualHoles);
    const Case cases[] = {{0, active, 1.0f},   {0, active, 0.6f},   {0, active, 0.3f},   {0, residual, 0.9f},
                          {0, residual, 0.5f}, {0, residual, 0.3f}, {1, 0, 1.0f},        {1, 0, 0.5f},
                          {1, 0, 0.2f},        {2, 0, 0.5f},        {2, 0, 0.2f},        {2, 0, 0.08f},
                          {5, 0, 0.7f},        {5, 0, 0.3f},        {5, 0, 0.0f}};
    const char* names[] = {"net_cover", "residual_cover", "streak_thickness", "", "", "streak_gathered"};
    double worst_overall = 0;
    for (const Case& c : cases) {
        foam.bind_pattern(*program, 0);
        program->set("u_amount", c.amount);
        program->set("u_holes", c.holes);
        program->set("u_function", c.function);
        const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*program, n, n, GL_R32F, GL_RED, GL_FLOAT, 1);
        double worst = 0, covered = 0;
        for (std::size_t i = 0; i < gpu.size(); ++i) {
            const double r = cells[i] / 255.0, g = noise[i] / 255.0;
            const double cpu = c.function == 0   ? step06::net_cover(c.amount, r, c.holes)
                               : c.function == 1 ? step06::residual_cover(c.amount, r, g)
                               : c.function == 2 ? step06::streak_thickness(c.amount, g)
                                                 : step06::streak_gathered(c.amount, r, g);
            worst = std::max(worst, std::abs(gpu[i] - cpu));
            covered += gpu[i];
        }
        std::printf("%-14s holes %.2f, amount %.2f: mean cover %.3f, worst |GPU - CPU| %.2g\n", names[c.function],
                    double(c.holes), double(c.amount), covered / double(gpu.size()), worst);
        EXPECT_LT(worst, 1e-5) << names[c.function] << ", amount " << c.amount;
        worst_overall = std::max(worst_overall, worst);
    }
    std::printf("the cover functions on the uploaded pattern: worst |GPU - CPU| %.2g (limit 1e-5)\n", worst_overall);
}

// The filtered cover in the renderer (foam_cover.frag's 3: filtered_net_cover) on mip levels 0, 2
// and 4 of the pattern texture, a pixel a texel of the level, through pattern_statistics. The CPU is given each texel's r and b
// two ways, with the same 2/255 off the variance:
//   - the level's own bytes, read back: only float arithmetic differs (limit 1e-4);
//   - the mean of the 2^L x 2^L uploaded bytes it averages, what the level should hold. But
//     glGenerateTextureMipmap makes each level from the one above and rounds it to 8 bits: up to L
//     bytes off (llvmpipe: 1.9 at level 2, 2.9 at level 4, about +0.5 a level on average). Where a
//     block is nearly flat the cover is steep in the variance (the spread's width is its square
//     root), so a byte of b can move a texel's cover by 0.05 (levels rounded to the nearest byte;
//     printed) and llvmpipe's levels move it by up to 0.095: the limit is 0.15 a texel, and 0.02
//     for the mean over the level (llvmpipe's bias upwards: 0.014 at level 4).
TEST_F(Step06Gpu, FilteredFoamCoverMatchesTheCpuOnTheMipLevels) {
    step06::FoamSimulation foam(factory());
    ocean::ShaderProgram* program = foam_cover_program();
    ASSERT_NE(program, nullptr);
    const step06::FoamPatternSettings settings;
    const int n = settings.size;
    const std::vector<std::uint8_t> uploaded = step06::foam_pattern_texture(settings);
    foam.bind_pattern(*program, 0);
    GLint texture = 0;  // FoamSimulation's pattern texture, to read its levels back
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    // pattern_statistics on the CPU: the mean and variance from r and b in bytes (or means of bytes).
    const auto statistics = [](double r, double b) {
        const double mean = r / 255.0;
        return std::pair{mean, std::max(b / 255.0 - mean * mean - 2.0 / 255.0, 0.0)};
    };
    struct Case {
        int function;  // 3 filtered_net_cover
        float holes, amount;
    };
    const float active = float(step06::kActiveHoles), residual = float(step06::kResidualHoles);
    const Case cases[] = {{3, active, 0.3f}, {3, active, 0.65f}, {3, residual, 0.2f}, {3, residual, 0.4f}, {3, residual, 0.65f}};
    double worst_own = 0, worst_box = 0, worst_mean = 0;
    for (const int level : {0, 2, 4}) {
        const int m = n >> level, box = 1 << level;
        std::vector<std::uint8_t> own(std::size_t(4 * m * m));
        glGetTextureImage(GLuint(texture), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(own.size()), own.data());
        if (level == 0) {
            ASSERT_EQ(own, uploaded) << "level 0 is foam_pattern_texture";
        }
        // Each texel's r and b as the means of the uploaded bytes it averages, and how far the
        // level's bytes are from them.
        std::vector<std::pair<double, double>> box_means(std::size_t(m * m));
        double off = 0, off_sum = 0;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                double r = 0, b = 0;
                for (int y = j * box; y < (j + 1) * box; ++y)
                    for (int x = i * box; x < (i + 1) * box; ++x) {
                        r += uploaded[std::size_t(4 * (y * n + x))];
                        b += uploaded[std::size_t(4 * (y * n + x) + 2)];
                    }
                const std::size_t t = std::size_t(j * m + i);
                box_means[t] = {r / (box * box), b / (box * box)};
                off = std::max({off, std::abs(own[4 * t] - box_means[t].first),
                                std::abs(own[4 * t + 2] - box_means[t].second)});
                off_sum += own[4 * t] - box_means[t].first;
            }
        std::printf("level %d: its r and b up to %.2f bytes from the box means of level 0 (r %+.2f on average)\n",
                    level, off, off_sum / (m * m));
        EXPECT_LE(off, double(level)) << "level " << level;
        for (const Case& c : cases) {
            foam.bind_pattern(*program, 0);
            program->set("u_amount", c.amount);
            program->set("u_holes", c.holes);
            program->set("u_function", c.function);
            program->set("u_lod", float(level));
            const std::vector<float> gpu =
                ocean_test::draw_full_screen<float>(*program, m, m, GL_R32F, GL_RED, GL_FLOAT, 1);
            const auto cpu = [&](double r, double b) {
                const auto [mean, variance] = statistics(r, b);
                return step06::filtered_net_cover(c.amount, mean, variance, c.holes);
            };
            double own_error = 0, box_error = 0, nearest_error = 0, covered = 0, box_covered = 0;
            for (std::size_t i = 0; i < gpu.size(); ++i) {
                const auto [r, b] = box_means[i];
                const double expected = cpu(r, b);
                own_error = std::max(own_error, std::abs(gpu[i] - cpu(own[4 * i], own[4 * i + 2])));
                box_error = std::max(box_error, std::abs(gpu[i] - expected));
                nearest_error = std::max(nearest_error, std::abs(cpu(std::round(r), std::round(b)) - expected));
                covered += gpu[i];
                box_covered += expected;
            }
            const double mean_error = (covered - box_covered) / double(gpu.size());
            std::printf("level %d, %-21s holes %.2f, amount %.2f: mean cover %.3f; worst |GPU - CPU| on the level's "
                        "bytes %.1e, on the box means %.3f (%.3f if rounded to the nearest byte), mean %+.4f\n",
                        level, "filtered_net_cover", double(c.holes),
                        double(c.amount), covered / double(gpu.size()), own_error, box_error, nearest_error,
                        mean_error);
            EXPECT_LT(own_error, 1e-4) << "level " << level << ", function " << c.function << ", amount " << c.amount;
            EXPECT_LT(box_error, 0.15) << "level " << level << ", function " << c.function << ", amount " << c.amount;
            EXPECT_LT(std::abs(mean_error), 0.02)
                << "level " << level << ", function " << c.function << ", amount " << c.amount;
            worst_own = std::max(worst_own, own_error);
            worst_box = std::max(worst_box, box_error);
            worst_mean = std::max(worst_mean, std::abs(mean_error));
        }
    }
    std::printf("the filtered cover on mip levels 0, 2, 4: worst |GPU - CPU| %.1e on the level's bytes (limit "
                "1e-4); on the box means of level 0 %.3f a texel (limit 0.15), %.4f over a level (limit 0.02)\n",
                worst_own, worst_box, worst_mean);
}

// The streaks' lines are read from a texture of the line's cover (foam_pattern.hpp's
// streak_lines_texture), so the texture filter averages the cover itself: level 0 is what was
// uploaded, each texel of levels 2 and 4 is the mean of the level-0 bytes it covers within a byte
// a level (glGenerateTextureMipmap rounds each level it makes from the one above), and the mean
// over a level is level 0's within half a byte a level. The renderer reads each level's bytes
// (foam_cover.frag's 4) as they are.
TEST_F(Step06Gpu, StreakLinesAreTheLineCoverAveraged) {
    step06::FoamSimulation foam(factory());
    ocean::ShaderProgram* program = foam_cover_program();
    ASSERT_NE(program, nullptr);
    const step06::FoamPatternSettings settings;
    const int n = settings.size;
    const std::vector<std::uint8_t> uploaded = step06::streak_lines_texture(settings);
    foam.bind_pattern(*program, 0);
    foam.bind_streak_lines(*program, 1);
    GLint texture = 0;
    glActiveTexture(GL_TEXTURE1);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    double level0_mean = 0;
    for (std::size_t i = 0; i < uploaded.size(); i += 4) level0_mean += uploaded[i];
    level0_mean /= double(n * n);
    for (const int level : {0, 2, 4}) {
        const int m = n >> level, box = 1 << level;
        std::vector<std::uint8_t> own(std::size_t(4 * m * m));
        glGetTextureImage(GLuint(texture), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(own.size()), own.data());
        if (level == 0) {
            ASSERT_EQ(own, uploaded) << "level 0 is streak_lines_texture";
        }
        double off = 0, mean = 0;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                double sum = 0;
                for (int y = j * box; y < (j + 1) * box; ++y)
                    for (int x = i * box; x < (i + 1) * box; ++x) sum += uploaded[std::size_t(4 * (y * n + x))];
                const double texel = own[std::size_t(4 * (j * m + i))];
                off = std::max(off, std::abs(texel - sum / (box * box)));
                mean += texel;
            }
        mean /= double(m * m);
        program->set("u_function", 4);
        program->set("u_lod", float(level));
        const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*program, m, m, GL_R32F, GL_RED, GL_FLOAT, 1);
        double worst = 0;
        for (std::size_t i = 0; i < gpu.size(); ++i)
            worst = std::max(worst, std::abs(gpu[i] - own[4 * i] / 255.0));
        std::printf("streak lines, level %d: texels up to %.2f bytes from the box means of level 0, the level's mean "
                    "%.2f against level 0's %.2f; read by the renderer, worst |GPU - bytes| %.1e\n",
                    level, off, mean, level0_mean, worst);
        EXPECT_LE(off, double(level)) << "level " << level;
        EXPECT_LE(std::abs(mean - level0_mean), 0.5 * level + 1e-9) << "level " << level;
        EXPECT_LT(worst, 1e-5) << "level " << level;
    }
}

TEST_F(Step06Gpu, FoamStaysInTheWorldWhenTheCameraMoves) {
    // The clipmap keeps each cell's foam where it is in the world: after the camera moves by
    // whole texels (and dt = 0, so nothing grows or decays), a cell seen before holds the same
    // foam, and a cell that entered the window starts at its steady state.
    const WindySea sea = windy_sea(factory(), 3.0, 1.6f);
    step06::FoamSimulation foam(factory());
    foam.resize(64);
    step06::FoamSettings settings;
    settings.injection = 3;
    foam.update(sea.gpu->maps(), all_cascades(), {0, 0}, {1, 0}, 0.0, settings);  // level 0: 1 m texels
    const auto before = foam.read_level(0);
    const glm::ivec2 origin_before = foam.window(0).origin;
    // Change the sea under the foam (another time), so that a kept cell and a restarted one differ.
    sea.gpu->simulate(5.5, step05::Backend::GpuFft, 1.6f);
    foam.update(sea.gpu->maps(), all_cascades(), {13.0, -7.0}, {1, 0}, 0.0, settings);
    const auto after = foam.read_level(0);
    const glm::ivec2 shift = foam.window(0).origin - origin_before;
    ASSERT_EQ(shift, glm::ivec2(13, -7));
    int kept = 0, changed_new = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const int bi = i + shift.x, bj = j + shift.y;  // the same world cell in the old window
            if (bi >= 0 && bi < 64 && bj >= 0 && bj < 64) {
                ASSERT_EQ(after[std::size_t(j) * 64 + i], before[std::size_t(bj) * 64 + bi]) << i << "," << j;
                ++kept;
            } else {
                changed_new += after[std::size_t(j) * 64 + i] != 0.0f;
            }
        }
    EXPECT_EQ(kept, (64 - 13) * (64 - 7));
    EXPECT_GT(changed_new, 0) << "entered cells start from the new sea's steady state";
}

// The renderer's foam_at, which fetches one clipmap level (two in a level's hand-over band),
// against the blend of all three levels it stands for (foam.hpp's foam_level_weights, in double).
// Each level holds one constant at every texel and mip level, whitecaps and residual apart, so the
// GPU's answer is the weights times the constants whatever the footprint: a wrong level, a wrong
// band or a missing second fetch shows as an error of order one.
TEST_F(Step06Gpu, FoamAtBlendsTheClipmapLevelsAsTheirWeightsSay) {
    const WindySea sea = windy_sea(factory(), 3.0, 1.6f);
    step06::FoamSimulation foam(factory());
    const int n = 64;
    foam.resize(n);
    foam.update(sea.gpu->maps(), all_cascades(), {0, 0}, {1, 0}, 0.0, step06::FoamSettings{});  // places the windows
    const std::array<glm::vec2, step06::kFoamLevels> constants{glm::vec2(1, 8), glm::vec2(2, 16), glm::vec2(4, 32)};
    for (int level = 0; level < step06::kFoamLevels; ++level)
        for (int mip = 0; (n >> mip) >= 1; ++mip)
            glClearTexSubImage(foam.texture(), mip, 0, 0, level, n >> mip, n >> mip, 1, GL_RG, GL_FLOAT,
                               &constants[std::size_t(level)]);
    ocean::ShaderProgram* program =
        cache("foam_at", {"common/shaders/fullscreen.vert", "step06_foam_sky/tests/foam_at.frag"}, {});
    ASSERT_NE(program, nullptr);
    // A grid over every window and past the largest: x from -250 to 870 m, z from -560 to 560 m.
    const int size = 512;
    const glm::dvec2 first(-250, -560);
    const double step = 1120.0 / size;
    foam.bind(*program, UNIT_FOAM);
    program->set("u_first", glm::vec2(first));
    program->set("u_step", float(step));
    // (whitecaps, residual) a texel
    const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*program, size, size, GL_RG32F, GL_RG, GL_FLOAT, 2);
    double worst = 0;
    std::array<int, step06::kFoamLevels> in_band{};  // points where a level hands over to the next
    int outside = 0;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const glm::dvec2 p = first + glm::dvec2(i, j) * step;
            const auto weights = step06::foam_level_weights(p, foam.windows());
            glm::dvec2 cpu(0.0);
            for (int level = 0; level < step06::kFoamLevels; ++level)
                cpu += weights[std::size_t(level)] * glm::dvec2(constants[std::size_t(level)]);
            const std::size_t texel = 2 * (std::size_t(j) * size + i);
            const glm::dvec2 got(gpu[texel], gpu[texel + 1]);
            worst = std::max({worst, std::abs(got.x - cpu.x), std::abs(got.y - cpu.y)});
            for (int level = 0; level < step06::kFoamLevels; ++level) {
                const double w = weights[std::size_t(level)];
                const bool finest = level == 0 || weights[std::size_t(level) - 1] == 0;
                if (w > 0 && w < 1 && finest) ++in_band[std::size_t(level)];
            }
            outside += cpu == glm::dvec2(0.0);
        }
    std::printf("foam_at: worst |GPU - CPU| %.2g (values up to 32); points in the bands of levels 0, 1, 2: %d, %d, "
                "%d; outside every window: %d\n",
                worst, in_band[0], in_band[1], in_band[2], outside);
    for (int level = 0; level < step06::kFoamLevels; ++level)
        EXPECT_GT(in_band[std::size_t(level)], 20) << "the grid must cross level " << level << "'s band";
    EXPECT_GT(outside, 20) << "the grid must reach past the largest window";
    // Float positions a few hundred metres out could move a weight by about 2e-5 over level 0's
    // 6.4 m band: 4e-4 on values up to 32 (on llvmpipe 0: the grid and the windows fall on binary
    // fractions). A level read in place of another, or a band's second fetch left out, is off by
    // 1 or more (the second fetch left out: 30.7).
    EXPECT_LT(worst, 1e-3);
}

struct Tessellated : Step06Gpu {
    std::unique_ptr<step05::OceanSimulation> ocean = calm_ocean();
    ocean::ShaderProgram* program = nullptr;
    void SetUp() override {
        Step06Gpu::SetUp();
        const std::string dir = "step06_foam_sky/shaders/";
        program = cache("ocean", {dir + "ocean.vert", dir + "ocean.tesc", dir + "ocean.tese", dir + "ocean.frag"}, {});
        ASSERT_NE(program, nullptr);
    }
    // Triangles the tessellator makes for one 16 m patch at the origin, seen from `eye`.
    long triangles(glm::vec3 eye, glm::vec3 target, float tess_scale) {
        step06::PatchGrid grid;
        grid.build(1, 16);
        const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 5000.0f) *
                             glm::lookAt(eye, target, std::abs(target.x - eye.x) + std::abs(target.z - eye.z) < 1e-3f
                                                          ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0));
        program->set("u_view_projection", vp);
        program->set("u_eye", eye);
        program->set("u_grid_offset", glm::vec2(0));
        program->set("u_tess_patch_size", 16.0f);
        program->set("u_tess_scale", tess_scale);
        program->set("u_frustum", ocean::frustum_planes(vp));
        program->set("u_max_displacement", 1.0f);
        program->set("u_patch_sizes", std::vector<float>{500, 137, 41, 12});
        glBindTextureUnit(0, ocean->displacement_texture());
        glBindTextureUnit(1, ocean->slopes_texture());
        program->set("u_displacement", 0);
        program->set("u_slopes", 1);
        program->set("u_foam", 2);  // samplers of different types may not share a unit
        program->set("u_sky", 3);
        ocean::Query query = ocean::make_query(GL_PRIMITIVES_GENERATED);
        const ocean_test::OneTexelTarget framebuffer;  // a draw needs a framebuffer, rasterised or not
        glUseProgram(program->id());
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginQuery(GL_PRIMITIVES_GENERATED, query.id());
        grid.draw(*program, step06::PatchView{vp, eye, glm::vec2(0.0f), 1.0f}, tess_scale, false);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glDisable(GL_RASTERIZER_DISCARD);
        GLuint64 count = 0;
        glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &count);
        return long(count);
    }
};

TEST_F(Tessellated, LevelFallsWithDistanceAsTheCpuFormulaSays) {
    long previous = 1L << 40;
    for (float height : {20.0f, 60.0f, 200.0f, 800.0f}) {
        // Straight above the patch centre every edge midpoint is at the same distance.
        const glm::vec3 eye(0, height, 0);
        const double distance = std::sqrt(double(height) * height + 64.0);  // to an edge midpoint, 8 m off
        const long expected = step06::triangles_for_uniform_level(step06::tessellation_level(distance, 16, 12));
        const long got = triangles(eye, glm::vec3(0, 0, 0), 12);
        EXPECT_EQ(got, expected) << "height " << height;
        EXPECT_LE(got, previous);
        previous = got;
        std::printf("eye %4.0f m above: %ld triangles (CPU: %ld)\n", double(height), got, expected);
    }
}

TEST_F(Tessellated, PatchesBehindTheCameraAreCulled) {
    const long in_front = triangles({0, 5, 40}, {0, 0, 0}, 12);
    const long behind = triangles({0, 5, 40}, {0, 0, 100}, 12);
    EXPECT_GT(in_front, 0);
    EXPECT_EQ(behind, 0) << "a patch behind the camera makes no triangles";
}

// The brightest texel of the cubemap, as a direction.
glm::vec3 brightest_direction(const step06::Sky& sky) {
    const int size = sky.size();
    std::vector<float> texels(std::size_t(size) * size * 6 * 4);
    glGetTextureImage(sky.cubemap(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    std::size_t best = 0;
    float best_luminance = -1;
    for (std::size_t i = 0; i < texels.size() / 4; ++i) {
        const float l = 0.2126f * texels[4 * i] + 0.7152f * texels[4 * i + 1] + 0.0722f * texels[4 * i + 2];
        if (l > best_luminance) { best_luminance = l; best = i; }
    }
    const int face = int(best / (std::size_t(size) * size));
    const int y = int(best / std::size_t(size)) % size, x = int(best % std::size_t(size));
    return step06::cube_texel_direction(face, x, y, size);
}

float degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

TEST_F(Step06Gpu, BrightestSkyTexelIsTheSunsGlowButNotItsDisc) {
    // The cubemap holds the glow around the sun (its brightest texels) but not the disc: the water
    // reflects the sun through the specular term, and a disc in the reflected sky would add it a
    // second time. Sunlight 6, the disc 40 times brighter, as the step's defaults.
    step06::Sky sky(factory(), 64);
    for (glm::vec3 sun : {glm::vec3(0.3f, 0.4f, -0.8f), glm::vec3(-0.9f, 0.15f, 0.2f), glm::vec3(0.1f, 0.95f, 0.2f)}) {
        step06::SkySettings s;
        s.to_sun = glm::normalize(sun);
        s.sun_radiance = glm::vec3(40.0f * 6.0f);
        s.cloud_cover = 0;
        sky.render(s);
        const float error = degrees_between(brightest_direction(sky), s.to_sun);
        EXPECT_LT(error, 2.0f) << "one texel of 64 is ~1.4 degrees";
        std::printf("sun (%.2f, %.2f, %.2f): brightest texel %.2f degrees away\n", s.to_sun.x, s.to_sun.y, s.to_sun.z,
                    double(error));
        // The disc alone would be 240; the glow at the sun is 0.68 of the sunlight (6) plus the sky.
        std::vector<float> texels(64 * 64 * 6 * 4);
        glGetTextureImage(sky.cubemap(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
        const float brightest = *std::max_element(texels.begin(), texels.end());
        EXPECT_LT(brightest, 10.0f) << "the sun's disc is in the cubemap: the water would reflect it twice";
    }
}

TEST_F(Step06Gpu, SkyFromAnImageAndItsFailures) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("ocean_sky_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // A 64 x 32 equirectangular image, grey with one bright spot at longitude 90 degrees (+z),
    // latitude 30 degrees up: column 48, row 10 of 32 (row 0 is straight up).
    ocean::Image image{64, 32, std::vector<std::uint8_t>(64 * 32 * 4, 60)};
    for (int y = 9; y <= 10; ++y)
        for (int x = 47; x <= 48; ++x) {
            std::uint8_t* p = &image.rgba[(std::size_t(y) * 64 + std::size_t(x)) * 4];
            p[0] = p[1] = p[2] = 255;
        }
    ASSERT_FALSE(ocean::save_png(image, (dir / "spot.png").string()));
    step06::Sky sky(factory(), 64);
    EXPECT_FALSE(sky.use_image((dir / "spot.png").string()));
    EXPECT_TRUE(sky.uses_image());
    sky.render({});
    const glm::vec3 expected(0, std::sin(glm::radians(30.0f)), std::cos(glm::radians(30.0f)));
    EXPECT_LT(degrees_between(brightest_direction(sky), expected), 8.0f) << "a texel of the image is 5.6 degrees";

    const auto missing = sky.use_image((dir / "missing.hdr").string());
    ASSERT_TRUE(missing);
    EXPECT_NE(missing->find("procedural"), std::string::npos) << *missing;
    EXPECT_FALSE(sky.uses_image());
    std::ofstream(dir / "corrupt.png") << "\x89PNG\r\n\x1a\n not an image at all";
    const auto corrupt = sky.use_image((dir / "corrupt.png").string());
    ASSERT_TRUE(corrupt);
    EXPECT_NE(corrupt->find("not a readable image"), std::string::npos) << *corrupt;
    EXPECT_FALSE(sky.uses_image());
    sky.render({});  // back on the procedural sky, without a GL error
    fs::remove_all(dir);
}


// sky.glsl's clouds against sky.hpp at |p| from 0.1 to 316 units of 900 m, negative ones too
// (the drift wraps at 1e5 m = 111 units; the horizon's projection adds a few). The hash is integer
// arithmetic, so it must agree exactly; the smooth noise to float rounding of p through five
// octaves (p x 2.03 each: 2e-5 here). Before the integer hash, sin(dot(p, ...)) * 43758 made the H100's and
// llvmpipe's skies different pictures.
TEST_F(Step06Gpu, CloudsAreTheSameOnEveryGpu) {
    constexpr int kPoints = 4096;
    std::mt19937 random(11);
    std::vector<glm::vec2> points;
    for (int i = 0; i < kPoints; ++i) {
        const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-1, 2.5)(random));
        std::uniform_real_distribution<double> signed_unit(-1, 1);
        points.emplace_back(float(scale * signed_unit(random)), float(scale * signed_unit(random)));
    }
    ocean::Buffer in = ocean::make_buffer(), out = ocean::make_buffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(points.size() * sizeof(glm::vec2)), points.data(), 0);
    glNamedBufferStorage(out.id(), GLsizeiptr(points.size() * sizeof(glm::vec2)), nullptr, 0);
    ocean::ShaderProgram program("eval_clouds", {std::string(OCEAN_SOURCE_DIR) + "/step06_foam_sky/tests/eval_clouds.comp"});
    ASSERT_FALSE(program.build()) << program.last_error();
    program.set("u_count", kPoints);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glUseProgram(program.id());
    glDispatchCompute(kPoints / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec2> gpu(kPoints);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec2)), gpu.data());
    double worst_hash = 0, worst_clouds = 0;
    for (int i = 0; i < kPoints; ++i) {
        const glm::dvec2 p(points[std::size_t(i)]);
        worst_hash = std::max(worst_hash, std::abs(gpu[std::size_t(i)].x -
                                                   step06::lattice_hash(int(std::floor(p.x)), int(std::floor(p.y)))));
        worst_clouds = std::max(worst_clouds, std::abs(gpu[std::size_t(i)].y - step06::clouds(p)));
    }
    std::printf("clouds: worst |GPU - CPU| hash %.1e, pattern %.1e\n", worst_hash, worst_clouds);
    EXPECT_EQ(worst_hash, 0.0);
    EXPECT_LT(worst_clouds, 1e-4);
}

// The fog's colour table (sky_horizon.glsl) against what it replaced, the cube read at
// Sky::horizon_lod towards the same azimuth, at 2048 random directions (looking up, down and level;
// the sun low, so that the horizon has its brightest and its darkest side), and its coordinate
// against sky.hpp's in double. The table interpolates linearly between 256 samples of a level whose
// ring round the horizon has 64 texels: it stands for the cube to 0.25 % of the horizon's
// brightest (measured 0.085 % on llvmpipe; texels placed half a texel off read 0.34 % and fail);
// the coordinate to float rounding.
TEST_F(Step06Gpu, TheFogsHorizonTableIsTheSkyCubeAtTheHorizon) {
    step06::Sky sky(factory(), 128);
    step06::SkySettings settings;
    settings.to_sun = glm::normalize(glm::vec3(0.8f, 0.15f, 0.3f));
    sky.render(settings);
    constexpr int kCount = 2048;
    std::mt19937 random(23);
    std::uniform_real_distribution<float> unit(-1, 1);
    std::vector<glm::vec4> directions;
    for (int i = 0; i < kCount; ++i) directions.emplace_back(unit(random), unit(random), unit(random), 0.0f);
    ocean::Buffer in = ocean::make_buffer(), out = ocean::make_buffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(directions.size() * sizeof(glm::vec4)), directions.data(), 0);
    glNamedBufferStorage(out.id(), GLsizeiptr(3 * directions.size() * sizeof(glm::vec4)), nullptr, 0);
    ocean::ShaderProgram* program = cache("eval_horizon", {"step06_foam_sky/tests/eval_horizon.comp"}, {});
    ASSERT_NE(program, nullptr);
    program->set("u_count", kCount);
    program->set("u_lod", sky.horizon_lod());
    sky.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glUseProgram(program->id());
    glDispatchCompute(kCount / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> gpu(3 * std::size_t(kCount));
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());
    double worst_coordinate = 0, worst_colour = 0, brightest = 0;
    for (std::size_t i = 0; i < std::size_t(kCount); ++i) {
        const double cpu = step06::horizon_coordinate({directions[i].x, directions[i].z});
        worst_coordinate = std::max(worst_coordinate, std::abs(gpu[3 * i].x - cpu));
        const glm::vec3 table(gpu[3 * i + 1]), cube(gpu[3 * i + 2]);
        for (int channel = 0; channel < 3; ++channel) {
            worst_colour = std::max(worst_colour, double(std::abs(table[channel] - cube[channel])));
            brightest = std::max(brightest, double(cube[channel]));
        }
    }
    std::printf("horizon table: worst |table - cube| %.2g of the brightest %.3g (%.3f %%), coordinate %.1e\n",
                worst_colour, brightest, 100 * worst_colour / brightest, worst_coordinate);
    ASSERT_GT(brightest, 0.1) << "the sky must be lit for the comparison to mean anything";
    EXPECT_LT(worst_colour, 0.0025 * brightest);
    EXPECT_LT(worst_coordinate, 1e-6);
}

// A float texture of width x height holding `texels` (RGBA), sampled linearly and clamped.
ocean::Texture float_texture(int width, int height, const std::vector<glm::vec4>& texels) {
    ocean::Texture t = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_RGBA32F, width, height);
    glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

// tonemap.frag, the pass itself, against tonemap.hpp in double for each curve, pixel by pixel,
// into a float target (before the rounding to 8 bits): a scene of random colours from 12 stops
// below mid-grey to 7 above, greys among them, plus the bloom (one texel: the same everywhere)
// and the dither. Left out: the pixels where the noise under the dither is within 1e-4 of a
// wrap, where a float and a double may fall on either side of it (a whole step apart); they
// must be few. Then what the dither is for, on the 8-bit target the screen gets: a slow gradient
// (3 steps over 96 columns) keeps its mean between the steps instead of a staircase.
TEST_F(Step06Gpu, TonemapPassIsTheCpuCurveAndLeavesNoBands) {
    const int width = 64, height = 32;
    std::mt19937 random(41);
    std::uniform_real_distribution<float> stops(-12, 7);
    std::vector<glm::vec4> scene;
    for (int i = 0; i < width * height; ++i) {
        const float grey = 0.18f * std::exp2(stops(random));
        glm::vec3 c = i % 4 == 0 ? glm::vec3(grey) : glm::vec3(0.18f) * glm::exp2(glm::vec3(stops(random), stops(random), stops(random)));
        scene.emplace_back(c, 1.0f);
    }
    const glm::vec3 bloom(0.5f, 0.7f, 1.2f);
    const float exposure = 1.3f, bloom_strength = 0.04f;
    ocean::Texture scene_texture = float_texture(width, height, scene), bloom_texture = float_texture(1, 1, {glm::vec4(bloom, 1)});
    const auto near_a_wrap = [](glm::dvec2 fragment) {
        const double inner = fragment.x * 0.06711056 + fragment.y * 0.00583715, noise = step06::interleaved_gradient_noise(fragment);
        const auto from_integer = [](double x) { return std::abs(x - std::round(x)); };
        return from_integer(inner) < 1e-4 || from_integer(52.9829189 * (inner - std::floor(inner))) < 1e-4 || from_integer(noise) < 1e-4;
    };
    for (const step06::Tonemapper curve : {step06::Tonemapper::Aces, step06::Tonemapper::Agx, step06::Tonemapper::None}) {
        ocean::ShaderProgram* program = cache("tonemap", {"common/shaders/fullscreen.vert", "step06_foam_sky/shaders/tonemap.frag"},
                                              {"TONEMAPPER " + std::to_string(int(curve))});
        ASSERT_NE(program, nullptr);
        program->set("u_scene", 0);
        program->set("u_bloom", 1);
        program->set("u_exposure", exposure);
        program->set("u_bloom_strength", bloom_strength);
        glBindTextureUnit(0, scene_texture.id());
        glBindTextureUnit(1, bloom_texture.id());
        const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*program, width, height, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4);
        double worst = 0;
        int skipped = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::dvec2 fragment(x + 0.5, y + 0.5);
                if (near_a_wrap(fragment)) {
                    ++skipped;
                    continue;
                }
                const std::size_t i = std::size_t(y * width + x);
                const glm::dvec3 cpu = step06::tonemap(glm::dvec3(scene[i]), glm::dvec3(bloom), exposure, bloom_strength, curve, fragment);
                for (int channel = 0; channel < 3; ++channel)
                    worst = std::max(worst, std::abs(double(gpu[4 * i + std::size_t(channel)]) - cpu[channel]));
            }
        std::printf("tonemap %d: worst |GPU - CPU| %.2e (%.3f of an 8-bit step), %d pixels by a wrap of the noise left out\n",
                    int(curve), worst, worst * 255, skipped);
        EXPECT_LT(worst, 5e-5) << int(curve);
        EXPECT_LT(skipped, width * height / 100) << int(curve);
    }
    // The slow gradient, through the curve "none" to the 8-bit target: value v steps is the linear
    // light whose sRGB code is v / 255, from 100 to 103 steps across the columns.
    const int columns = 96, column_width = 8, rows = 128;
    std::vector<glm::vec4> gradient;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns * column_width; ++x) {
            const double encoded = (100.0 + (x / column_width) / 32.0) / 255.0;
            gradient.emplace_back(glm::vec3(float(std::pow((encoded + 0.055) / 1.055, 2.4))), 1.0f);
        }
    ocean::Texture gradient_texture = float_texture(columns * column_width, rows, gradient);
    ocean::ShaderProgram* none = cache("tonemap", {"common/shaders/fullscreen.vert", "step06_foam_sky/shaders/tonemap.frag"}, {"TONEMAPPER 2"});
    ASSERT_NE(none, nullptr);
    none->set("u_exposure", 1.0f);
    none->set("u_bloom_strength", 0.0f);
    glBindTextureUnit(0, gradient_texture.id());
    const std::vector<std::uint8_t> bytes =
        ocean_test::draw_full_screen<std::uint8_t>(*none, columns * column_width, rows, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    double worst_mean = 0;
    for (int column = 0; column < columns; ++column) {
        double sum = 0;
        for (int y = 0; y < rows; ++y)
            for (int x = column * column_width; x < (column + 1) * column_width; ++x) sum += bytes[4 * std::size_t(y * columns * column_width + x)];
        worst_mean = std::max(worst_mean, std::abs(sum / (rows * column_width) - (100.0 + column / 32.0)));
    }
    std::printf("tonemap on 8 bits: a 3-step gradient's column means within %.3f steps of the true values\n", worst_mean);
    EXPECT_LT(worst_mean, 0.05) << "bands: the dither does not keep a gradient's mean between the steps";
}

// PostProcess::bloom, the passes themselves (bloom_down.frag first and down, bloom_up.frag), against
// bloom.hpp in double: a 64 x 48 scene of dim water (below the threshold) with bright glints and
// a bright patch, through five levels (16 x 12 down to 1 x 1) and back up; level 0, which the
// tonemapper adds, texel by texel. The scene is given as half floats (its RGBA16F target), so the
// CPU starts from the same values; every level is stored in RGBA16F too (about 5e-4 relative a
// pass), and a GPU may quantise its filter weights to 8 bits: the tolerance is 1 % of the
// brightest texel.
TEST_F(Step06Gpu, BloomChainIsTheCpuChain) {
    const glm::ivec2 size(64, 48);
    std::mt19937 random(43);
    std::uniform_real_distribution<float> dim(0.0f, 1.5f), bright(20.0f, 300.0f);
    std::vector<glm::vec4> texels;
    step06::BloomImage scene(size.x, size.y);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            glm::vec3 c(dim(random), dim(random), dim(random));
            if (random() % 23 == 0) c = glm::vec3(bright(random), bright(random), bright(random));  // glints
            if (x >= 40 && x < 48 && y >= 8 && y < 14) c = glm::vec3(6.0f, 4.0f, 2.0f);          // a bright patch
            for (int i = 0; i < 3; ++i) c[i] = glm::unpackHalf1x16(glm::packHalf1x16(c[i]));
            texels.emplace_back(c, 1.0f);
            scene.at(x, y) = glm::dvec3(c);
        }
    step06::PostProcess post;
    post.resize(size);
    glTextureSubImage2D(post.scene_texture(), 0, 0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, texels.data());
    const std::string dir = "step06_foam_sky/shaders/";
    ocean::ShaderProgram* first = cache("bloom_first", {"common/shaders/fullscreen.vert", dir + "bloom_down.frag"}, {"FIRST_LEVEL 1"});
    ocean::ShaderProgram* down = cache("bloom_down", {"common/shaders/fullscreen.vert", dir + "bloom_down.frag"}, {});
    ocean::ShaderProgram* up = cache("bloom_up", {"common/shaders/fullscreen.vert", dir + "bloom_up.frag"}, {});
    ASSERT_TRUE(first != nullptr && down != nullptr && up != nullptr);
    const float threshold = 2.5f;
    ocean::VertexArray vao = ocean::make_vertex_array();
    post.bloom(*first, *down, *up, threshold, vao.id());
    const std::vector<step06::BloomImage> cpu = step06::bloom_chain(scene, threshold, step06::kBloomLevels);
    const step06::BloomImage& level0 = cpu.front();
    ASSERT_EQ(cpu.size(), 5u);
    std::vector<glm::vec4> gpu(std::size_t(level0.width) * std::size_t(level0.height));
    glGetTextureImage(post.bloom_texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(gpu.size() * sizeof(glm::vec4)), gpu.data());
    double worst = 0, brightest = 0;
    for (int y = 0; y < level0.height; ++y)
        for (int x = 0; x < level0.width; ++x)
            for (int channel = 0; channel < 3; ++channel) {
                const double expected = level0.at(x, y)[channel];
                brightest = std::max(brightest, expected);
                worst = std::max(worst, std::abs(double(gpu[std::size_t(y * level0.width + x)][channel]) - expected));
            }
    std::printf("bloom: worst |GPU - CPU| %.3g of the brightest %.3g (%.3f %%)\n", worst, brightest, 100 * worst / brightest);
    ASSERT_GT(brightest, 1.0) << "the glints must bloom for the comparison to mean anything";
    EXPECT_LT(worst, 0.01 * brightest);
}

}  // namespace
