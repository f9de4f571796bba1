// step01_sine2d's exercises (./ocean exercise step01_sine2d N): for each, the file and function
// it empties, the stub, the task, the hint, and the check that holds the learner's function to
// the chapter's CPU reference. tools/exercise gathers every chapter's (add_step's EXERCISES).
#include "tools/exercise.hpp"

#include "tools/exercise_inputs.hpp"
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
         "Write wave_height: wave i arrives as u_waves[i] = (w, a, phase, 0), w = 2 pi / wavelength already, and\n"
         "its height at x is a sin(x w + phase). Without it the plot is a flat line.",
         "u_waves[i].x is w (radians per metre), .y the amplitude a, .z the phase (-t phi, reduced on the CPU): "
         "a * sin(x * w + phase). The phase is added, not multiplied.",
         "", {},
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step01::sum_of_sines(kStep01Waves, a.x, kCheckTime); },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step01_sine2d", 2, "The slope of a sine", "sine_sum.glsl", "float wave_slope(int i, float x) {",
         "    // TODO (exercise 2): d/dx of wave i's height at x.\n    return 0.0;\n",
         "Write wave_slope, the derivative of a sin(x w + phase) with respect to x. The plot uses it to draw\n"
         "its line equally thick on steep slopes: without it the line thins where the wave is steep.",
         "The chain rule brings w out of the sine, and the amplitude stays: a w cos(x w + phase). The notes' 2.2 "
         "writes cos(...) alone, without w a: that is the slope of a wave of one radian per metre and amplitude 1.",
         "", {},
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines_slope(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step01::sum_of_sines_slope(kStep01Waves, a.x, kCheckTime);
                 },
                 1e-4, -20, 20, set_step01_waves);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
