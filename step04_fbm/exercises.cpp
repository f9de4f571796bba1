// step04_fbm's exercises (./ocean exercise step04_fbm N): for each, the file and function
// it empties, the stub, the task, the hint, and the check that holds the learner's function to
// the chapter's CPU reference. tools/exercise gathers every chapter's (add_step's EXERCISES).
#include "tools/exercise.hpp"

#include "step04_fbm/fbm.hpp"
#include "step03_lighting/normals.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

std::vector<Exercise> chapter() {
    return {
        {"step04_fbm", 1, "The exp-sine wave and its derivatives", "fbm.glsl", "vec3 wave_shape(float theta) {",
         "    // TODO (exercise 1): (W, W', W'') of the exp-sine wave, mean removed. For now, a sine.\n"
         "    return vec3(sin(theta), cos(theta), -sin(theta));\n",
         "Write wave_shape for SHAPE 1: W = e^(sin theta - 1) - 0.46575961 (its mean, so the sea stays at y = 0),\n"
         "W' = dW/dtheta and W'' = d2W/dtheta2. W' makes the normals, W'' the domain warp's Jacobian.\n"
         "The starter is step02's sine: round crests, as wide as the troughs.",
         "d/dtheta e^(sin theta - 1) = e^(sin theta - 1) cos theta; differentiate that product again: "
         "e^(sin theta - 1)(cos^2 theta - sin theta). The mean is subtracted from W only.",
         "", {},
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "wave_shape(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step04::ShapeValue w = step04::wave_shape(step04::Shape::ExpSine, a.x);
                     return glm::dvec3(w.value, w.first, w.second);
                 },
                 1e-4, -10, 10);
         }},
        {"step04_fbm", 2, "The normal from the gradient", "fbm.glsl", "vec3 fbm_normal(vec2 gradient) {",
         "    // TODO (exercise 2): the unit normal from (dh/dx, dh/dz).\n    return vec3(0.0, 1.0, 0.0);\n",
         "Write fbm_normal: with the tangents T = (1, dh/dx, 0) and B = (0, dh/dz, 1), N = B x T, normalised.\n"
         "The starter's normal is straight up: the sea is lit as if flat.",
         "B x T = (-dh/dx, 1, -dh/dz) before normalising; T x B points down, into the water (then the light is "
         "on the wrong side of every wave).",
         "", {},
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "fbm_normal(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step03::Vec3 n = step03::normal({0.0, a.x, a.y});
                     return glm::dvec3(n.x, n.y, n.z);
                 },
                 1e-4, -2, 2);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
