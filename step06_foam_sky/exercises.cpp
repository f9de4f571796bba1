// step06_foam_sky's exercises (./ocean exercise step06_foam_sky N): for each, the file and function
// it empties, the stub, the task, the hint, the formula (--hint), the flags the step runs with, and
// the check that holds the learner's function to the chapter's CPU reference. The exercise tool
// (exercises/) gathers every chapter's (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step03_lighting/exercise_vectors.hpp"
#include "step06_foam_sky/cascade_bands.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/fog.hpp"
#include "step06_foam_sky/shading.hpp"
#include "step06_foam_sky/tessellation.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

// step06's fog, as the amount of fog colour (surface black, fog white), for eyes 2-52 m up and
// points on the sea within 1.5 km.
constexpr double kFogDensity = 0.0012, kFogFalloff = 0.02;
const char* kFogRay = "vec3(100.0 * a.x, 27.0 + 25.0 * a.y, 100.0 * a.z), vec3(1500.0 * b.x, 3.0 * b.y, 1500.0 * b.z)";

// step06's tessellation uniforms in the checks: an eye 12 m up, 16 m patches, scale 12 (the defaults).
const glm::dvec3 kTessEye(10.0, 12.0, -20.0);
constexpr double kTessPatch = 16, kTessScale = 12;

// Exercise 7's cases: tiles from 50 m to 7.5 km, divided by ratios between 2 and 4.7 (not only the
// chapter's 3.7, 3.3, 3.55: the split must follow any tiles), on grids of 64 to 512. The check's
// program (kBandsDriver) builds the same and prints them before the bands, so that the two copies
// cannot drift apart unnoticed.
std::array<double, step06::kCascades> band_case_tiles(int i) {
    const double r1 = 2 + (i % 7) * 0.45, r2 = 2 + (i % 5) * 0.6, r3 = 2 + (i % 3) * 0.9;
    const double l0 = 50 + 37.5 * i;
    return {l0, l0 / r1, l0 / r1 / r2, l0 / r1 / r2 / r3};
}
int band_case_resolution(int i) { return 64 << (i % 4); }

// Compiled with the learner's cascade_bands.cpp: for each case, its four tiles, its resolution, then
// the four bands' (low, high).
const char* kBandsDriver = R"(#include "step06_foam_sky/cascade_bands.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int i = 0; i < cases; ++i) {
        const double r1 = 2 + (i % 7) * 0.45, r2 = 2 + (i % 5) * 0.6, r3 = 2 + (i % 3) * 0.9;
        const double l0 = 50 + 37.5 * i;
        const std::array<double, step06::kCascades> tiles{l0, l0 / r1, l0 / r1 / r2, l0 / r1 / r2 / r3};
        const int resolution = 64 << (i % 4);
        std::printf("%.17g %.17g %.17g %.17g %d", tiles[0], tiles[1], tiles[2], tiles[3], resolution);
        for (const step06::Band& b : step06::cascade_bands(tiles, resolution)) std::printf(" %.17g %.17g", b.low, b.high);
        std::printf("\n");
    }
}
)";

std::vector<double> bands_reference(int i) {
    const auto tiles = band_case_tiles(i);
    const int resolution = band_case_resolution(i);
    std::vector<double> values(tiles.begin(), tiles.end());
    values.push_back(resolution);
    for (const step06::Band& b : step06::cascade_bands(tiles, resolution)) {
        values.push_back(b.low);
        values.push_back(b.high);
    }
    return values;
}

std::vector<Exercise> chapter() {
    using step06::Microfacet;
    return {
        {"step06_foam_sky", 1, "Schlick's Fresnel", "shading.glsl", "float fresnel_schlick(float cos_theta, float f0) {",
         "    // TODO (exercise 1): how much light the water reflects, seen at cos_theta from the normal.\n"
         "    return 0.0;\n",
         "Write fresnel_schlick: the share of light the water reflects, seen at cos_theta from the normal\n"
         "(light.md, section 3). Schlick's approximation blends two ends: looking straight down (cos theta = 1) water\n"
         "reflects f0 (0.02), at grazing (cos theta = 0) it reflects everything; between them the weight of\n"
         "'everything' grows as the fifth power of how far the view is from head-on, 1 - cos theta. Write the\n"
         "blend so that both ends come out right, and keep cos theta in [0, 1] (a normal bent past 90 degrees\n"
         "gives a negative one). Without it the sea reflects nothing: no sky in the water, no glint.",
         "Try both ends: F(1) must be f0 (the notes' (1 - cos theta)^5 alone reflects nothing head-on) and "
         "F(0) must be 1. Clamp cos theta.",
         "F = f0 + (1 - f0) (1 - clamp(cos_theta, 0, 1))^5",
         {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "fresnel_schlick(dot(n, v), 0.02)",
                                  [](const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3&, double) {
                                      return step06::fresnel_schlick(glm::dot(n, v), 0.02);
                                  },
                                  1e-4);
         }},
        {"step06_foam_sky", 2, "The microfacet specular", "shading.glsl",
         "vec3 specular_term(vec3 n, vec3 v, vec3 l, Roughness r, float f0, vec3 sun) {",
         "    // TODO (exercise 2): the sun's light that the microfacets reflect towards v.\n"
         "    return vec3(0.0);\n",
         "Write specular_term from the parts above it in shading.glsl (light.md, section 3): the sun's light that the\n"
         "water's microfacets mirror towards the eye. Only the facets whose normal is the halfway vector H\n"
         "between v and l send the sun into the eye: D counts how many face H (anisotropic_distribution), G\n"
         "how many of those are neither shadowed from l nor hidden from v (Smith's height-correlated masking,\n"
         "built from anisotropic_lambda of both directions), F how much each reflects (Fresnel at the angle\n"
         "between v and H). The Cook-Torrance BRDF divides D G F by 4 N.L N.V; this function returns the\n"
         "radiance, the BRDF times the sun's irradiance. Nothing when the sun or the eye is below the surface.\n"
         "r is rougher along the wind than across it. Without it there is no sun glint.",
         "Fresnel takes the angle between v and H, not N.V (the facets that mirror the sun face H). The "
         "irradiance brings an N.L that cancels the BRDF's. Height-correlated masking puts both Lambdas in one "
         "denominator. The check's roughness is twice as rough along a wind at (0.6, 0.8) as across it: use "
         "r's D and Lambda, not alpha alone.",
         "0 if N.L <= 0 or N.V <= 0; H = normalize(v + l), D = anisotropic_distribution(n, H, r), "
         "G = 1 / (1 + anisotropic_lambda(n, v, r) + anisotropic_lambda(n, l, r)), F = fresnel_schlick(dot(v, H), f0); "
         "return sun * D * G * F / (4 N.V)",
         {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl",
                               "specular_term(n, v, l, wind_roughness(n, alpha, 0.5 * alpha, vec2(0.6, 0.8)), 0.02, vec3(1.0)).x",
                               [](const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha) {
                                   return step06::specular_factor(step03::to_vec3(n), step03::to_vec3(v),
                                                                  step03::to_vec3(l), {alpha, 0.5 * alpha, 0.6, 0.8},
                                                                  0.02, Microfacet::Ggx);
                               },
                               1e-4);
         }},
        // derived: the lesson gives the method, not this answer
        {"step06_foam_sky", 3, "Foam, exact at any frame rate", "foam_step.glsl",
         "float foam_step(float foam, float injection_rate, float decay_rate, float dt) {",
         "    // TODO (exercise 3): the foam after dt seconds. The starter is the explicit step.\n"
         "    return clamp(foam * exp(-decay_rate * dt) + injection_rate * dt, 0.0, 1.0);\n",
         "Write foam_step: the foam after a frame of dt seconds (foam.md, section 3). The foam u obeys du/dt = q - r u:\n"
         "made at the rate q = injection_rate, fading at the rate r = decay_rate, both held through the frame.\n"
         "The starter takes one explicit step, whose result depends on dt. Solve the equation exactly over the\n"
         "frame from u(0) = foam instead (a linear equation of the first order: u relaxes exponentially towards\n"
         "the level where making and fading balance), then clamp to [0, 1]. The step runs on a fixed 0.2 s a\n"
         "frame (--dt 0.2: five frames a second of sea time, whatever your screen's rate) with foam that fades\n"
         "fast (foam_decay=10) and forms easily (foam_threshold=1): there the starter makes about twice the\n"
         "foam. Try --dt 0.02 as well: the exact step's foam does not change.",
         "For r dt -> 0 your step must tend to foam + q dt, and for r dt -> infinity to q / r. Mind r = 0 and "
         "float's cancellation in 1 - e^{-x} for small x: exp_mean.glsl's mean_of_exp handles both.",
         "u(dt) = foam e^{-r dt} + q (1 - e^{-r dt}) / r = foam * exp(-x) + injection_rate * dt * mean_of_exp(x), "
         "x = decay_rate * dt (mean_of_exp(x) = (1 - e^{-x}) / x, in exp_mean.glsl); clamped to [0, 1]",
         {"--dt", "0.2", "--set", "foam_decay=10", "--set", "foam_threshold=1"},
         [](const fs::path& work) {
             return check_values(
                 work, "foam_step.glsl", "foam_step(a.x, 20.0 * a.y, 5.0 * a.z, 0.5 * b.x)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     step06::FoamSettings s;
                     s.threshold = 1;  // J = 0: the injection rate is s.injection
                     s.injection = 20 * a.y;
                     s.decay_rate = 5 * a.z;
                     return step06::foam_step(a.x, 0.0, 0.5 * b.x, s);
                 },
                 1e-4, 0, 1);
         }, kDerived},
        {"step06_foam_sky", 4, "The tessellation level", "tessellation.glsl", "float edge_level(vec2 a, vec2 b) {",
         "    // TODO (exercise 4): how many segments the edge from a to b (x, z, at y = 0) is cut into.\n"
         "    return 16.0;\n",
         "Write edge_level: how many segments the edge from a to b (x, z, at y = 0) is cut into (sea.md, section 2). A\n"
         "segment should cover about the same part of the screen wherever the edge lies. How does an edge's\n"
         "size on screen fall with its distance from the eye (u_eye)? Make the level follow that, scaled by\n"
         "u_tess_scale * u_tess_patch_size, and clamp it to [1, 64] (GL's guaranteed maximum). Two patches share\n"
         "each edge and must cut it alike, or a crack opens between them: measure the distance to a point\n"
         "both compute the same. The step shows the levels as colours (view=tessellation): the starter cuts\n"
         "every edge into 16, one colour everywhere, too coarse near the camera and wasted far away.",
         "Use the edge's midpoint, at y = 0, and its distance to u_eye in 3D (a patch's centre differs from its "
         "neighbour's); the level falls as 1 / distance; clamp to [1, 64].",
         "midpoint = (0.5 (a.x + b.x), 0, 0.5 (a.y + b.y)); "
         "level = clamp(u_tess_scale * u_tess_patch_size / max(length(midpoint - u_eye), 1e-3), 1, 64)",
         {"--set", "view=tessellation"},
         [](const fs::path& work) {
             return check_values(
                 work, "tessellation.glsl", "edge_level(300.0 * a.xy, 300.0 * a.zw)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const glm::dvec3 midpoint(150.0 * (a.x + a.z), 0.0, 150.0 * (a.y + a.w));
                     const glm::dvec3 d = midpoint - kTessEye;
                     return step06::tessellation_level(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), kTessPatch, kTessScale);
                 },
                 1e-4, -1, 1, [](const ocean::ShaderProgram& p) {
                     p.set("u_eye", glm::vec3(kTessEye));
                     p.set("u_tess_patch_size", float(kTessPatch));
                     p.set("u_tess_scale", float(kTessScale));
                 });
         }},
        {"step06_foam_sky", 5, "The GGX distribution, normalised", "shading.glsl",
         "float ggx_distribution(float n_dot_h, float alpha) {",
         "    // TODO (exercise 5): GGX's D(h). The starter is step03's Blinn-Phong lobe, not normalised.\n"
         "    return pow(max(n_dot_h, 0.0), 2.0 / (alpha * alpha) - 2.0);\n",
         "Write ggx_distribution: D(h), the density of microfacet normals around h for slopes of spread alpha\n"
         "(light.md, section 3). GGX's shape in N.H is 1 / ((N.H)^2 (alpha^2 - 1) + 1)^2: flat for a rough sea, a tall\n"
         "narrow peak at N.H = 1 for a smooth one. D must also be normalised: the integral of D (N.H) over the\n"
         "hemisphere is 1 (the facets' projected area is the surface's), so a rougher sea spreads the sun's\n"
         "glint wider and dimmer without making light. Derive the factor that normalises the shape (integrate\n"
         "in cos^2 theta over the hemisphere). The starter's lobe has about the right shape and the wrong size.",
         "At N.H = 1, D must be 1 / (pi alpha^2): alpha = 0.1 gives 31.8. Without the pi the glint is pi times "
         "too bright.",
         "D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2)",
         {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "ggx_distribution(max(dot(n, normalize(v + l)), 0.0), alpha)",
                               [](const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha) {
                                   const glm::dvec3 h = glm::normalize(v + l);
                                   return step06::microfacet_distribution(std::max(glm::dot(n, h), 0.0), alpha,
                                                                          step06::Microfacet::Ggx);
                               },
                               1e-4);
         }},
        {"step06_foam_sky", 6, "Height fog", "fog.glsl", "vec3 apply_fog(vec3 colour, vec3 eye, vec3 p, vec3 fog_colour) {",
         "    // TODO (exercise 6): fog between the eye and p. The starter's fog is as thick at any height.\n"
         "    return mix(fog_colour, colour, exp(-u_fog_density * length(p - eye)));\n",
         "Write apply_fog: the fog between the eye and the point p (air.md, section 1). Its density falls with\n"
         "height, rho(y) = u_fog_density e^{-beta y}, beta = u_fog_falloff. Light from p reaches the eye dimmed by e^{-tau},\n"
         "tau the density summed along the segment from the eye to p (the optical depth), and fog_colour makes\n"
         "up the rest. Parametrise the segment, integrate the exponential in closed form, and mind the level\n"
         "ray (p.y = eye.y), whose limit is finite. The step looks straight down from 150 m (--camera top):\n"
         "the starter's fog, as thick up there as on the water, greys the whole sea.",
         "A level ray must give tau = u_fog_density e^{-beta eye.y} |p - eye|, not a division by zero; exp_mean.glsl's "
         "mean_of_exp(x) = (1 - e^{-x}) / x takes that limit for you.",
         "tau = u_fog_density e^{-beta eye.y} |p - eye| (1 - e^{-beta dy}) / (beta dy), beta = u_fog_falloff, dy = p.y - eye.y "
         "(= u_fog_density * exp(-beta * eye.y) * length(p - eye) * mean_of_exp(beta * dy)); "
         "return mix(fog_colour, colour, exp(-tau))",
         {"--camera", "top"},
         [](const fs::path& work) {
             return check_values(
                 work, "fog.glsl", std::string("apply_fog(vec3(0.0), ") + kFogRay + ", vec3(1.0)).x",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     return step06::fog_amount({100 * a.x, 27 + 25 * a.y, 100 * a.z}, {1500 * b.x, 3 * b.y, 1500 * b.z},
                                               kFogDensity, kFogFalloff);
                 },
                 1e-4, -1, 1, [](const ocean::ShaderProgram& p) {
                     p.set("u_fog_density", float(kFogDensity));
                     p.set("u_fog_falloff", float(kFogFalloff));
                 });
         }},
        {"step06_foam_sky", 7, "The cascades' band split", "cascade_bands.cpp",
         "std::array<Band, kCascades> cascade_bands(const std::array<double, kCascades>& patch_sizes, int resolution) {",
         "    // TODO (exercise 7): each cascade's band of |k|, so that every wave is in exactly one. For now\n"
         "    // the notes' stack: each cascade keeps all that its grid resolves, and the bands overlap.\n"
         "    std::array<Band, kCascades> bands{};\n"
         "    for (int c = 0; c < kCascades; ++c) bands[std::size_t(c)] = {0.0, ocean::kPi * resolution / patch_sizes[std::size_t(c)]};\n"
         "    return bands;\n",
         "Write cascade_bands (C++, in cascade_bands.cpp; sea.md, section 1): which wavenumbers |k| each\n"
         "cascade keeps. Four tiles of sides l_0 > l_1 > l_2 > l_3 (patch_sizes; the chapter writes l_c), each an N x N grid (N =\n"
         "resolution), each resolve the waves from their tile's longest up to the shortest their grid can\n"
         "hold. Stacked as they are (the notes' 5.4, and the starter), every wavelength two tiles share is\n"
         "counted twice or more, and the sea comes out up to four times too energetic. Give each cascade a\n"
         "band [low, high) so that the bands tile [0, k_max) without a gap or an overlap: cascade 0 holds the\n"
         "longest waves, from k = 0; a cascade c > 0 takes over where its own tile holds\n"
         "kWavesPerTileAtBoundary wavelengths (well resolved by the cascade before); the last band ends at\n"
         "the shortest wave the last grid resolves. Derive each boundary's wavenumber. ./ocean check compiles\n"
         "your file with a small program and compares 200 sets of tiles and grids with the chapter's split.",
         "A boundary is one number that ends band c - 1 and starts band c. A wave's wavenumber is "
         "k = 2 pi / its wavelength; a grid of N points over a tile l_c resolves waves down to two points long.",
         "low_0 = 0; low_c = 2 pi kWavesPerTileAtBoundary / patch_sizes[c] (c > 0) and high_{c-1} = low_c; "
         "high_3 = pi resolution / patch_sizes[3] (ocean::kPi)",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "cascade_bands.cpp", kBandsDriver, 200, bands_reference, 1e-12);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
