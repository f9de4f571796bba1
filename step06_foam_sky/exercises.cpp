// step06_foam_sky's exercises (./ocean exercise step06_foam_sky N): for each, the file and function
// it empties, the stub, the task, the hint, and the check that holds the learner's function to
// the chapter's CPU reference. tools/exercise gathers every chapter's (add_step's EXERCISES).
#include "tools/exercise.hpp"

#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/fog.hpp"
#include "step06_foam_sky/shading.hpp"
#include "step06_foam_sky/tessellation.hpp"

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

std::vector<Exercise> chapter() {
    using step06::Microfacet;
    return {
        {"step06_foam_sky", 1, "Schlick's Fresnel", "shading.glsl", "float fresnel_schlick(float cos_theta, float f0) {",
         "    // TODO (exercise 1): how much light the water reflects, seen at cos_theta from the normal.\n"
         "    return 0.0;\n",
         "Write fresnel_schlick: F = F0 + (1 - F0)(1 - cos theta)^5, with cos theta clamped to [0, 1].\n"
         "Without it the sea reflects nothing: no sky in the water, no glint.",
         "Looking straight down (cos theta = 1) water reflects F0 = 0.02; at grazing (cos theta = 0), "
         "everything (1). Check both ends of your formula, and clamp cos theta: a normal bent past 90 degrees "
         "gives a negative one.",
         "", {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "fresnel_schlick(dot(n, v), 0.02)",
                                  [](const Vec3& n, const Vec3& v, const Vec3&, double) {
                                      return step06::fresnel_schlick(step03::dot(n, v), 0.02);
                                  },
                                  1e-4);
         }},
        {"step06_foam_sky", 2, "The microfacet specular", "shading.glsl",
         "vec3 specular_term(vec3 n, vec3 v, vec3 l, Roughness r, float f0, vec3 sun) {",
         "    // TODO (exercise 2): the sun's reflection towards v: sun * D * G * F / (4 N.V).\n"
         "    return vec3(0.0);\n",
         "Write specular_term from the parts above it: H = normalize(V + L), D = anisotropic_distribution(N, H, r),\n"
         "G = 1 / (1 + anisotropic_lambda(N, V, r) + anisotropic_lambda(N, L, r)), F = fresnel_schlick(V.H, f0);\n"
         "return sun D G F / (4 N.V), and nothing when the sun or the eye is below the surface (N.L <= 0 or\n"
         "N.V <= 0). r is rougher along the wind than across it. Without it there is no sun glint.",
         "Fresnel takes V.H here, not N.V (the microfacets that reflect the sun face H); the 4 N.V in the "
         "denominator is N.V alone (N.L cancels with the irradiance); return vec3(0.0) for N.L <= 0 or N.V <= 0. "
         "The check's roughness is twice as rough along a wind at (0.6, 0.8) as across it: use the anisotropic "
         "D and Lambda, not alpha alone.",
         "", {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl",
                               "specular_term(n, v, l, wind_roughness(n, alpha, 0.5 * alpha, vec2(0.6, 0.8)), 0.02, vec3(1.0)).x",
                               [](const Vec3& n, const Vec3& v, const Vec3& l, double alpha) {
                                   return step06::specular_factor(n, v, l, {alpha, 0.5 * alpha, 0.6, 0.8}, 0.02,
                                                                  Microfacet::Ggx);
                               },
                               1e-4);
         }},
        {"step06_foam_sky", 3, "Foam, exact at any frame rate", "foam_step.glsl",
         "float foam_step(float foam, float injection_rate, float decay_rate, float dt) {",
         "    // TODO (exercise 3): the foam after dt seconds. The starter is the explicit step.\n"
         "    return clamp(foam * exp(-decay_rate * dt) + injection_rate * dt, 0.0, 1.0);\n",
         "Write foam_step: solve df/dt = q - r f over the frame, q = injection_rate and r = decay_rate held\n"
         "constant, from f(0) = foam, and clamp to [0, 1]. The starter's explicit step makes 6 % more foam at\n"
         "6 frames a second than at 60.",
         "The solution of df/dt = q - r f is f(dt) = f e^{-r dt} + q (1 - e^{-r dt}) / r; for r dt -> 0 it tends "
         "to f + q dt (mind the division by r = 0, and float's cancellation in 1 - e^{-x} for tiny x).",
         "", {},
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
         }},
        {"step06_foam_sky", 4, "The tessellation level", "tessellation.glsl", "float edge_level(vec2 a, vec2 b) {",
         "    // TODO (exercise 4): how many segments the edge from a to b (x, z, at y = 0) is cut into.\n"
         "    return 16.0;\n",
         "Write edge_level: the level falls as 1 / distance from the eye (u_eye) to the edge's midpoint, so that\n"
         "a segment covers about the same part of the screen near and far: u_tess_scale * u_tess_patch_size /\n"
         "distance, clamped to [1, 64]. The starter cuts every edge into 16: too coarse near the camera, wasted far\n"
         "away (view=tessellation shows it).",
         "Use the midpoint of the edge (so the two patches that share it compute the same level and no crack "
         "opens), at y = 0, and its distance to u_eye in 3D; clamp to [1, 64].",
         "", {},
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
         "Write ggx_distribution: D(h) = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), the density of microfacet\n"
         "normals around h for slopes of spread alpha. It is normalised: the integral of D (N.H) over the\n"
         "hemisphere is 1, so a rougher sea spreads the sun's glint wider and dimmer without making light. The\n"
         "starter's lobe has the right shape and the wrong size.",
         "At N.H = 1, D = 1 / (pi alpha^2): a smooth sea (small alpha) has a tall, narrow peak. Without the pi the "
         "glint is pi times too bright; check D(1) for alpha = 0.1 (31.8).",
         "", {},
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "ggx_distribution(max(dot(n, normalize(v + l)), 0.0), alpha)",
                               [](const Vec3& n, const Vec3& v, const Vec3& l, double alpha) {
                                   const Vec3 h = step03::normalize({v.x + l.x, v.y + l.y, v.z + l.z});
                                   return step06::microfacet_distribution(std::max(step03::dot(n, h), 0.0), alpha,
                                                                          step06::Microfacet::Ggx);
                               },
                               1e-4);
         }},
        {"step06_foam_sky", 6, "Height fog", "fog.glsl", "vec3 apply_fog(vec3 colour, vec3 eye, vec3 p, vec3 fog_colour) {",
         "    // TODO (exercise 6): fog between the eye and p. The starter's fog is as thick at any height.\n"
         "    return mix(fog_colour, colour, exp(-u_fog_density * length(p - eye)));\n",
         "Write apply_fog: the fog's density falls with height, rho(y) = u_fog_density e^{-u_fog_falloff y}. Sum it\n"
         "along the segment from eye to p (the optical depth tau: the integral has a closed form), and keep\n"
         "e^{-tau} of the colour, the rest fog_colour. The starter's fog ignores height: a camera up high sees\n"
         "as much as one on deck.",
         "Parametrise the segment as eye + s (p - eye), s in [0, 1]: tau = |p - eye| * density e^{-f eye.y} * "
         "(1 - e^{-f dy}) / (f dy), dy = p.y - eye.y. A level ray (f dy -> 0) needs the limit 1.",
         "", {},
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
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
