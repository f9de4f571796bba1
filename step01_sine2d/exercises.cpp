// step01_sine2d's exercises (./ocean exercise step01_sine2d N): for each, the file and function
// it empties, the stub, the task, the hint, the formula (--hint), the flags the step runs with, and
// the check that holds the learner's function to the chapter's CPU reference. The exercise tool
// (exercises/) gathers every chapter's (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step01_sine2d/exercise_inputs.hpp"
#include "step01_sine2d/sine_sum.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

// step01's uniforms as its main.cpp sets them: (w, a, -t phi mod 2 pi, 0) per wave.
void set_step01_waves(const ocean::ShaderProgram& p) {
    std::vector<glm::vec4> packed;
    for (const step01::Wave& w : kStep01Waves)
        packed.emplace_back(float(step01::angular_wavenumber(w)), float(w.amplitude),
                            float(step01::phase_at(step01::phase_rate(w), kCheckTime)), 0.0f);
    p.set("u_wave_count", int(packed.size()));
    p.set("u_waves", packed);
}

std::vector<Exercise> chapter() {
    return {
        {"step01_sine2d", 1, "One sine wave", "sine_sum.glsl", "float wave_height(int i, float x) {",
         "    // TODO (exercise 1): the height of wave i at x.\n    return 0.0;\n",
         "Write wave_height: the height of wave i at x. Wave i arrives as u_waves[i] = (w, a, phase, 0): its\n"
         "angular wavenumber w = 2 pi / wavelength (radians per metre), its amplitude a (metres) and its phase\n"
         "-t phi (reduced on the CPU). A sine repeats every 2 pi: build its argument so that it grows by 2 pi\n"
         "over one wavelength and is shifted by the phase, then scale the sine so that the crest stands a above\n"
         "rest. Without it the plot is a flat line.",
         "Look at the argument of the sine: w multiplies x, the phase is added to it (not multiplied), and the "
         "amplitude scales the sine's value, not its argument.",
         "wave_height = a sin(x w + phase) = u_waves[i].y * sin(x * u_waves[i].x + u_waves[i].z)",
         {},
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step01::sum_of_sines(kStep01Waves, a.x, kCheckTime); },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step01_sine2d", 2, "The slope of a sine", "sine_sum.glsl", "float wave_slope(int i, float x) {",
         "    // TODO (exercise 2): d/dx of wave i's height at x.\n    return 0.0;\n",
         "Write wave_slope: d/dx of wave i's height, a sin(x w + phase) (exercise 1), the steepness of the\n"
         "wave at x. Differentiate it with the chain rule: what does the derivative of the inside, x w + phase,\n"
         "bring out, and what happens to the amplitude? The plot uses the slope to draw its line equally thick\n"
         "on steep slopes: without it the line thins where the wave is steep.",
         "The chain rule brings out the derivative of x w + phase, and the amplitude stays. The notes' 2.2 writes "
         "cos(...) alone: the slope of a wave of one radian per metre and amplitude 1.",
         "wave_slope = a w cos(x w + phase) = u_waves[i].y * u_waves[i].x * cos(x * u_waves[i].x + u_waves[i].z)",
         {},
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines_slope(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step01::sum_of_sines_slope(kStep01Waves, a.x, kCheckTime);
                 },
                 1e-4, -20, 20, set_step01_waves);
         }},
        // derived: exercise 2 takes the slope by the chain rule; the bend is the same chain rule taken again, whose result no page gives
        {"step01_sine2d", 3, "The curvature of a sine", "sine_sum.glsl", "float wave_curvature(int i, float x) {",
         "    // TODO (exercise 3): d2/dx2 of wave i's height at x.\n    return 0.0;\n",
         "Write wave_curvature: how fast wave i's slope (exercise 2) itself changes along x, the second\n"
         "derivative of a sin(x w + phase); where the slopes are gentle, as on the sea, it is the curvature,\n"
         "how sharply the surface bends. Derive it with exercise 2's method: the chain rule, once more, on\n"
         "your slope. What does the inside bring out this time, and which way does the result point at a\n"
         "crest? Then compare the waves: which of them makes most of the sum's bend? The step runs with\n"
         "show_curvature, which draws the sum's curvature in pink on the same axis (1/m): a flat line on\n"
         "the x axis until you write it.",
         "Differentiate your slope, not the height: the chain rule brings out w a second time. At a crest "
         "the slope goes from rising to falling: the bend must be negative there.",
         "wave_curvature = -a w^2 sin(x w + phase) = -u_waves[i].y * u_waves[i].x * u_waves[i].x * "
         "sin(x * u_waves[i].x + u_waves[i].z): each wave's bend is weighted by w^2, so the short waves make most of it",
         {"--set", "show_curvature=true"},
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines_curvature(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step01::sum_of_sines_curvature(kStep01Waves, a.x, kCheckTime);
                 },
                 1e-4, -20, 20, set_step01_waves);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
