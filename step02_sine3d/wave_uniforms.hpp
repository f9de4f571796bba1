// Hands a list of directional waves to waves.glsl: one vec4 (d.x, d.z, w, a) and one reduced
// phase per wave. Shared by the step and by the GPU read-back test, so the test checks the
// same upload the program uses.
#pragma once

#include "common/shader.hpp"
#include "step02_sine3d/waves.hpp"

#include <algorithm>
#include <vector>

namespace step02 {

constexpr int kMaxWaves = 16;  // MAX_WAVES in waves.glsl

inline void upload_waves(const ocean::ShaderProgram& program, const std::vector<DirectionalWave>& waves,
                         double time) {
    const std::size_t count = std::min<std::size_t>(waves.size(), kMaxWaves);
    std::vector<glm::vec4> packed;
    std::vector<float> phases;
    for (std::size_t i = 0; i < count; ++i) {
        const Direction d = direction(waves[i]);
        packed.emplace_back(float(d.x), float(d.z), float(angular_wavenumber(waves[i])),
                            float(waves[i].amplitude));
        phases.push_back(float(step01::phase_at(phase_rate(waves[i]), time)));
    }
    program.set("u_wave_count", int(count));
    program.set("u_waves", packed);
    program.set("u_wave_phases", phases);
}

// Hands a ripple to ripple.glsl: (c.x, c.z, w, a) and its reduced phase.
inline void upload_ripple(const ocean::ShaderProgram& program, const Ripple& ripple, double time) {
    const double w = kTwoPi / ripple.wavelength;
    program.set("u_ripple", glm::vec4(float(ripple.x), float(ripple.z), float(w), float(ripple.amplitude)));
    program.set("u_ripple_phase", float(step01::phase_at(ripple.speed * w, time)));
}

}  // namespace step02
