// step02_sine3d's exercises (./ocean exercise step02_sine3d N): for each, the file and function
// it empties, the stub, the task, the hint, the formula (--hint), the flags the step runs with, and
// the check that holds the learner's function to the chapter's CPU reference. The exercise tool
// (exercises/) gathers every chapter's (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step02_sine3d/exercise_inputs.hpp"
#include "step02_sine3d/wave_uniforms.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

std::vector<Exercise> chapter() {
    return {
        {"step02_sine3d", 1, "Waves with a direction", "waves.glsl", "float wave_height(vec2 xz) {",
         "    // TODO (exercise 1): the sum of the directional waves at xz.\n    return 0.0;\n",
         "Write wave_height: the sum of the u_wave_count waves at xz. A directional wave travels along its\n"
         "unit direction d, and its crests are straight lines across d: its height depends on xz only through\n"
         "how far along d the point lies. Turn step01's wave a sin(x w + phase) into one along d, and sum them.\n"
         "u_waves[i] = (d.x, d.z, w, a): mind the letters, GLSL's .w is the amplitude a and the wavenumber w\n"
         "is .z. The phase is its own array, u_wave_phases[i]. Without it the sea is flat.",
         "How far along d the point xz lies is a projection: one product of two vectors. The phase is "
         "u_wave_phases[i], not a component of u_waves[i].",
         "wave_height(xz) = sum over i of a sin(dot(d, xz) w + phase) = "
         "sum of u_waves[i].w * sin(dot(u_waves[i].xy, xz) * u_waves[i].z + u_wave_phases[i])",
         {},
         [](const fs::path& work) {
             return check_values(
                 work, "waves.glsl", "wave_height(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step02::height(kStep02Waves, a.x, a.y, kCheckTime); },
                 1e-4, -60, 60,
                 [](const ocean::ShaderProgram& p) { step02::upload_waves(p, kStep02Waves, kCheckTime); });
         }},
        {"step02_sine3d", 2, "A facet's normal", "facet.glsl", "vec3 facet_normal(vec3 along_x, vec3 along_y) {",
         "    // TODO (exercise 2): the unit normal of the facet spanned by the two edges, facing up.\n"
         "    return vec3(0.0, 1.0, 0.0);\n",
         "Write facet_normal: the unit normal of the flat facet whose edges are along_x and along_y (the\n"
         "world position's screen-space derivatives, dFdx and dFdy). A normal is perpendicular to both edges:\n"
         "which product of two vectors gives such a vector? Make it unit length, and make it face up (y >= 0)\n"
         "whichever way round the edges come. The starter's normal is straight up: every facet is shaded alike\n"
         "and the waves' shape is hard to read (step02 draws with facet_shading on).",
         "The order of the two edges (and the screen's orientation) decides which side a cross product points "
         "to: turn the normal over when its y is negative.",
         "n = normalize(cross(along_x, along_y)); return n.y < 0.0 ? -n : n",
         {},
         [](const fs::path& work) {
             return check_vector(
                 work, "facet.glsl", "facet_normal(a.xyz, b.xyz)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const step02::Vector n = step02::facet_normal({a.x, a.y, a.z}, {b.x, b.y, b.z});
                     return glm::dvec3(n.x, n.y, n.z);
                 },
                 1e-4, -1, 1);
         }},
        // derived: the README measures a wave's phase along a direction; a ring's, and how its height falls as it spreads, no page gives
        {"step02_sine3d", 3, "A ring from a bobbing source", "ripple.glsl", "float ripple_height(vec2 xz) {",
         "    // TODO (exercise 3): the height of the ring of waves at xz.\n    return 0.0;\n",
         "Write ripple_height: a source bobbing up and down at c sends out a steady ring of waves of one\n"
         "wavelength. Exercise 1's wave measures how far along its direction d a point lies; a ring's crests\n"
         "are circles about c instead, travelling outwards: what distance takes the place of dot(d, xz)?\n"
         "Then its height: a crest's energy, which\n"
         "grows as the square of the amplitude, is spread round a circle that grows as the ring spreads,\n"
         "and none is lost. Derive how the amplitude must fall with the distance r so that the energy\n"
         "crossing every circle in a second is the same, given that it is u_ripple.w one wavelength from c;\n"
         "nearer than that (the source itself) keep it u_ripple.w. u_ripple = (c.x, c.z, w, a), the phase\n"
         "-t phi in u_ripple_phase. The step runs with a ripple (ripple_amplitude): without it, none.",
         "The crest's circle is 2 pi r long: the energy per metre of crest falls as 1 / r, and the "
         "energy goes as the amplitude squared. The wavelength is 2 pi / w.",
         "r = distance(xz, c); ripple_height = a sqrt(wavelength / max(r, wavelength)) sin(r w + phase), "
         "wavelength = 2 pi / w: u_ripple.w * sqrt(6.2831853 / u_ripple.z / max(r, 6.2831853 / u_ripple.z)) "
         "* sin(r * u_ripple.z + u_ripple_phase)",
         {"--set", "ripple_amplitude=0.6", "--set", "ripple_wavelength=6", "--set", "wave_count=1"},
         [](const fs::path& work) {
             return check_values(
                 work, "ripple.glsl", "ripple_height(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step02::ripple_height(kStep02Ripple, a.x, a.y, kCheckTime);
                 },
                 1e-4, -60, 60,
                 [](const ocean::ShaderProgram& p) { step02::upload_ripple(p, kStep02Ripple, kCheckTime); });
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
