// step03_lighting's exercises (./ocean exercise step03_lighting N): for each, the file and function
// it empties, the stub, the task, the hint, the formula (--hint), the flags the step runs with, and
// the check that holds the learner's function to the chapter's CPU reference. The exercise tool
// (exercises/) gathers every chapter's (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step02_sine3d/exercise_inputs.hpp"
#include "step02_sine3d/wave_uniforms.hpp"
#include "step03_lighting/exercise_vectors.hpp"
#include "step03_lighting/light_uniforms.hpp"
#include "step03_lighting/lighting.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

// step03's light with the sun at `sun`, a white sun, the default water and shininess 64.
step03::Light step03_light(const step03::Vec3& sun) {
    step03::Light light;
    light.to_sun = sun;
    light.sun = {1, 1, 1};
    light.water = {0.05, 0.25, 0.35};
    light.ambient = {0.02, 0.04, 0.06};
    light.shininess = 64;
    return light;
}

// step03's light_terms on the GPU, one term: its uniforms set as step03_light says.
Verdict check_step03_term(const fs::path& work, const std::string& term, double (*pick)(const step03::LightTerms&)) {
    static const step03::Vec3 sun = step03::normalize({0.4, 0.5, -0.3});
    static const glm::dvec3 fixed_sun(sun.x, sun.y, sun.z);
    const step03::Light light = step03_light(sun);
    return check_glsl(
        work, "lighting.glsl", "light_terms(n, v)." + term,
        [&](const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3&, double) {
            return pick(step03::light_terms(step03::to_vec3(n), step03::to_vec3(v), light));
        },
        1e-4,
        [&](const ocean::ShaderProgram& p) {
            p.set("u_to_sun", glm::vec3(float(sun.x), float(sun.y), float(sun.z)));
            p.set("u_sun_color", glm::vec3(1.0f));
            p.set("u_water_color", glm::vec3(float(light.water.r), float(light.water.g), float(light.water.b)));
            p.set("u_ambient_color", glm::vec3(float(light.ambient.r), float(light.ambient.g), float(light.ambient.b)));
            p.set("u_shininess", float(light.shininess));
        },
        &fixed_sun);
}

std::vector<Exercise> chapter() {
    return {
        {"step03_lighting", 1, "Lambert and Blinn-Phong", "lighting.glsl", "LightTerms light_terms(vec3 normal, vec3 to_eye) {",
         "    // TODO (exercise 1): ambient, Lambert diffuse and Blinn-Phong specular.\n"
         "    LightTerms t;\n    t.ambient = u_ambient_color;\n    t.diffuse = vec3(0.0);\n    t.specular = vec3(0.0);\n"
         "    return t;\n",
         "Write light_terms' diffuse and specular (the ambient is given). Diffuse, Lambert's law: a surface\n"
         "receives sunlight in proportion to how squarely it faces the sun (u_to_sun, L), and none when it faces\n"
         "away; the water's colour tints what the sun's colour brings. Specular, Blinn-Phong: a glint where the\n"
         "normal lies close to the direction halfway between the eye (to_eye) and the sun, narrowed by the\n"
         "exponent u_shininess; a sun behind the surface makes no glint. Without them the sea is a flat,\n"
         "fogged grey-blue shape, ambient colour alone.",
         "The halfway direction is the normalised sum of the two unit vectors, not the reflection of either; "
         "the specular must be 0 wherever N.L <= 0, even where N.H is large.",
         "n_dot_l = dot(normal, u_to_sun); H = normalize(to_eye + u_to_sun); "
         "diffuse = u_water_color * u_sun_color * max(n_dot_l, 0); "
         "specular = u_sun_color * (n_dot_l > 0 ? pow(max(dot(normal, H), 0), u_shininess) : 0)",
         {},
         [](const fs::path& work) {
             const Verdict diffuse = check_step03_term(work, "diffuse.y", [](const step03::LightTerms& t) { return t.diffuse.g; });
             if (!diffuse.pass) return diffuse;
             return check_step03_term(work, "specular.x", [](const step03::LightTerms& t) { return t.specular.r; });
         }},
        {"step03_lighting", 2, "The slope of the waves", "wave_gradient.glsl", "vec3 wave_height_gradient(vec2 xz) {",
         "    // TODO (exercise 2): (h, dh/dx, dh/dz). For now the height alone: a sea lit as if flat.\n"
         "    return vec3(wave_height(xz), 0.0, 0.0);\n",
         "Write wave_height_gradient: (h, dh/dx, dh/dz) in one loop over the waves: the height as step02\n"
         "sums it, a sin(angle) with angle = dot(d, xz) w + phase, and its two partial derivatives. Differentiate\n"
         "one wave along x, then along z, with the chain rule: how fast does angle change when x moves?\n"
         "u_waves[i] = (d.x, d.z, w, a), the phase in u_wave_phases[i]. The normal, and so all the light, comes\n"
         "from the derivatives: the starter's are zero, a sea lit as if it were flat.",
         "d(angle)/dx brings out w and the direction's x component, and the amplitude stays. The notes' 2.2 "
         "forgets the w a.",
         "angle = dot(d, xz) w + phase; h += a sin(angle); (dh/dx, dh/dz) += a w cos(angle) (d.x, d.z), i.e. "
         "result.yz += u_waves[i].z * u_waves[i].w * cos(angle) * u_waves[i].xy",
         {},
         [](const fs::path& work) {
             return check_vector(
                 work, "wave_gradient.glsl", "wave_height_gradient(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const auto g = step03::height_and_gradient(kStep02Waves, a.x, a.y, kCheckTime);
                     return glm::dvec3(g.height, g.dh_dx, g.dh_dz);
                 },
                 1e-4, -60, 60, [](const ocean::ShaderProgram& p) { step02::upload_waves(p, kStep02Waves, kCheckTime); });
         }},
        // derived: the README builds Blinn-Phong's halfway vector; Phong's mirrored sun, and the exponent that gives it the same glint, no page gives
        {"step03_lighting", 3, "Phong's glint, as wide as Blinn-Phong's", "lighting.glsl",
         "float phong_specular(vec3 normal, vec3 to_eye) {",
         "    // TODO (exercise 3): Phong's glint: the sun mirrored about the normal, against the eye.\n"
         "    return 0.0;\n",
         "Write phong_specular, Phong's glint, older than Blinn-Phong's: a mirror sends the sun's light (towards\n"
         "u_to_sun, L) off along one direction M, the sun mirrored about the normal (the README's figure draws\n"
         "it), and the glint is the eye's direction (to_eye, V) against M, raised to\n"
         "an exponent. First find M from L and the unit normal: split L into its part along the normal and its\n"
         "part across it; a mirror keeps one and turns the other round. Then the exponent: at the same\n"
         "u_shininess s Phong's lobe is much narrower than Blinn-Phong's. For an eye in the plane of\n"
         "N and L, compare the angle between M and V with the angle between N and H, and choose the exponent\n"
         "so that both glints fall off alike near their top (expand the cosines for small angles). No glint\n"
         "from a sun behind the surface. The step runs with specular=phong and view=specular: a black sea\n"
         "until you write it, then glints close to Blinn-Phong's (specular=blinn_phong) in size, but rounder.",
         "L's part along the normal is (N.L) N; M keeps it and turns the rest round. When the eye moves by "
         "an angle x from M, the halfway vector moves by only x / 2 from N; and ln cos x is about -x^2 / 2.",
         "M = 2 (N.L) N - L; phong_specular = N.L > 0 ? max(M.V, 0)^(s / 4) : 0, i.e. "
         "pow(max(dot(2.0 * dot(normal, u_to_sun) * normal - u_to_sun, to_eye), 0.0), 0.25 * u_shininess): "
         "cos(2x)^(s/4) and cos(x)^s are both about exp(-s x^2 / 2)",
         {"--set", "specular=phong", "--set", "view=specular"},
         [](const fs::path& work) {
             static const step03::Vec3 sun = step03::normalize({0.4, 0.5, -0.3});
             static const glm::dvec3 fixed_sun(sun.x, sun.y, sun.z);
             const step03::Light light = step03_light(sun);
             return check_glsl(
                 work, "lighting.glsl", "phong_specular(n, v)",
                 [&](const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3&, double) {
                     return step03::phong_specular(step03::to_vec3(n), step03::to_vec3(v), light);
                 },
                 1e-4, [&](const ocean::ShaderProgram& p) { step03::upload_light(p, light); }, &fixed_sun);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
