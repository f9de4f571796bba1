// step04_fbm's exercises (./ocean exercise step04_fbm N): for each, the file and function
// it empties, the stub, the task, the hint, the formula (--hint), the flags the step runs with, and
// the check that holds the learner's function to the chapter's CPU reference. The exercise tool
// (exercises/) gathers every chapter's (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step02_sine3d/exercise_inputs.hpp"
#include "step04_fbm/fbm.hpp"
#include "step04_fbm/fbm_uniforms.hpp"
#include "step03_lighting/normals.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

// Exercise 3's check: the whole warped sum, (h, dh/dx, dh/dz), with the learner's chain rule, held
// to fbm.hpp's exact gradient on the step's default sea (two cascades of 20 waves, warp 4).
Verdict check_warped_gradient(const fs::path& work) {
    step04::CascadeSettings s;
    s.wave_count = 20;
    s.base_amplitude = 1.2;
    const std::vector<step04::Cascade> cascades = step04::make_cascades(s, 2, 0.37);
    constexpr double kWarp = 4;
    step04::FbmUniforms uniforms;  // the step's own uniform buffer, filled as main.cpp fills it
    return check_vector(
        work, "fbm.glsl", "fbm_height_gradient(a.xy)",
        [&](const glm::dvec4& a, const glm::dvec4&) {
            const step03::HeightGradient g =
                step04::height_gradient(cascades, step04::Shape::ExpSine, kWarp, a.x, a.y, kCheckTime);
            return glm::dvec3(g.height, g.dh_dx, g.dh_dz);
        },
        1e-4, -40, 40, [&](const ocean::ShaderProgram& p) { uniforms.upload(p, cascades, kWarp, kCheckTime); });
}

std::vector<Exercise> chapter() {
    return {
        {"step04_fbm", 1, "The exp-sine wave and its derivatives", "fbm.glsl", "vec3 wave_shape(float theta) {",
         "    // TODO (exercise 1): (W, W', W'') of the exp-sine wave, mean removed. For now, a sine.\n"
         "    return vec3(sin(theta), cos(theta), -sin(theta));\n",
         "Write wave_shape for SHAPE 1, the exp-sine wave: W = e^(sin theta - 1) less its mean over a period,\n"
         "0.46575961 (so that the sea's mean level stays at y = 0), and its first two derivatives W' = dW/dtheta\n"
         "and W'' = d2W/dtheta2. Derive them with the chain rule (an exponential of a function) and then the\n"
         "product rule. W' makes the normals, W'' the domain warp's Jacobian. The starter is step02's sine:\n"
         "round crests, as wide as the troughs; watch them sharpen when you save.",
         "The mean is a constant: it comes off W only. The derivative of e^(sin theta - 1) is the exponential "
         "itself times the derivative of its exponent; W'' is the derivative of that product.",
         "W = e^(sin theta - 1) - 0.46575961, W' = e^(sin theta - 1) cos theta, "
         "W'' = e^(sin theta - 1) (cos^2 theta - sin theta)",
         {},
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
         "Write fbm_normal: the unit normal of the surface y = h(x, z) from gradient = (dh/dx, dh/dz). The\n"
         "surface has two tangents: a step of one metre along x rises by dh/dx, one along z by dh/dz. The normal\n"
         "is perpendicular to both: build the two tangents from the gradient, combine them, normalise. Which\n"
         "order of the two points up, out of the water? The starter's normal is straight up: the sea is lit as if\n"
         "flat.",
         "Try your normal on a flat sea (gradient 0): it must be (0, 1, 0). The other order of the cross product "
         "points into the water, and the light lands on the wrong side of every wave.",
         "T = (1, dh/dx, 0), B = (0, dh/dz, 1), N = normalize(B x T) = normalize(vec3(-gradient.x, 1.0, -gradient.y))",
         {},
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "fbm_normal(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step03::Vec3 n = step03::normal({0.0, a.x, a.y});
                     return glm::dvec3(n.x, n.y, n.z);
                 },
                 1e-4, -2, 2);
         }},
        {"step04_fbm", 3, "The warp's gradient: the chain rule", "fbm.glsl",
         "void warp_chain_rule(vec2 d, float w, float a, vec3 shape, vec2 slope, inout vec3 total, inout mat2 jacobian) {",
         "    // TODO (exercise 3): this wave's gradient at p, and the warp's Jacobian past its push. For now\n"
         "    // the gradient where the wave is read, as if q did not move with p.\n"
         "    total.yz += slope;\n",
         "Write warp_chain_rule, the exact gradient through the domain warp (README \"The normal stays exact\").\n"
         "Wave i is read at the warped point q_i(p), which the waves before it pushed: q_{i+1} = q_i - u_warp a\n"
         "slope, slope = a w W'(theta) d its gradient at q_i (the loop computes it, and moves q after your\n"
         "function). The light needs the gradient at p, where the point is drawn. First, by the chain rule: if p\n"
         "moves by dp, q_i moves by J dp, J = dq_i/dp (jacobian, the identity for the first wave); what then is\n"
         "this wave's gradient with respect to p? Add it to total.yz. Second, differentiate the push with respect\n"
         "to p to find how J changes past this wave (slope depends on q only through theta, whose gradient is w\n"
         "d), and update jacobian. The starter adds the gradient at q_i: right only for warp = 0. The step runs\n"
         "with a strong warp, close up (warp=8, camera_distance=30): watch the shading of the short waves.",
         "Add the gradient with the Jacobian of the point this wave reads, before you update it, and mind the "
         "transpose: df = slope . (J dp) = (J^T slope) . dp. The push's derivative is the Hessian of a W(w d.q): "
         "a w^2 W'' d d^T.",
         "total.yz += transpose(jacobian) * slope; "
         "jacobian = (I - u_warp a^2 w^2 W''(theta) d d^T) jacobian = "
         "(mat2(1.0) - u_warp * a * a * w * w * shape.z * outerProduct(d, d)) * jacobian",
         {"--set", "warp=8", "--set", "camera_distance=30"},
         check_warped_gradient},
        // derived: the lesson differentiates and centres exp(sin - 1) only; this shape is the learner's
        {"step04_fbm", 4, "Another sharp wave: GPU Gems' sine cubed", "fbm.glsl", "vec3 power_sine_shape(float theta) {",
         "    // TODO (exercise 4): (W, W', W'') of ((1 + sin theta) / 2)^3, scaled and centred. For now, a sine.\n"
         "    return vec3(sin(theta), cos(theta), -sin(theta));\n",
         "Write power_sine_shape, the shape of --set shape=power_sine: GPU Gems 1 (Finch, chapter 1)\n"
         "sharpens a sine by lifting it to [0, 1] and raising it to a power k, ((1 + sin theta) / 2)^k;\n"
         "here k = 3. Like the exp-sine (\"A sharper wave shape\" and \"The sea's level\"), it must be\n"
         "scaled to the same crest-to-trough height, 1 - e^-2 (so that the shapes compare like with like),\n"
         "and have its mean over a period taken out (so that the sea rests at y = 0); then return\n"
         "(W, W', W''), W' for the normals and W'' for the warp's Jacobian. Find the mean as \"The sea's level\"\n"
         "finds e^-1 I0(1): expand the power, and average each power of sin over a period. The derivatives are the\n"
         "chain rule (a power of a function) and then the product rule. The step runs with\n"
         "shape=power_sine: the starter is a sine twice as high, round crests as wide as the troughs.",
         "Expanded, the cube is a polynomial in sin theta: the odd powers average 0 over a period, sin^2 "
         "averages 1/2. The scale multiplies all three of W, W', W'', the mean comes off W only; d/dtheta of "
         "(1 + sin theta) / 2 is cos theta / 2.",
         "u = (1 + sin theta) / 2, A = 1 - e^-2 = 0.86466472: W = A (u^3 - 5/16), W' = A (3/2) u^2 cos theta, "
         "W'' = A (3/2) (u cos^2 theta - u^2 sin theta)",
         {"--set", "shape=power_sine"},
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "power_sine_shape(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step04::ShapeValue w = step04::power_sine_shape(a.x);
                     return glm::dvec3(w.value, w.first, w.second);
                 },
                 1e-4, -10, 10);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
