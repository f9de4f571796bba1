// Hands the fBm cascades to fbm.glsl: a uniform buffer of (d.x, d.z, w, a), (phase, 0, 0, 0)
// per wave, in std140 layout, refreshed every frame because the phases move. Shared by the step
// and the GPU read-back test.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"
#include "step04_fbm/fbm.hpp"

#include <array>
#include <vector>

namespace step04 {

class FbmUniforms {
public:
    FbmUniforms() {
        buffer_ = ocean::make_buffer();
        ocean::buffer_data(buffer_, sizeof(GpuWave) * kMaxCascades * kMaxWavesPerCascade, nullptr, GL_DYNAMIC_DRAW);
    }

    void upload(const ocean::ShaderProgram& program, const std::vector<Cascade>& cascades, double warp,
                double time) {
        std::vector<GpuWave> data(std::size_t(kMaxCascades) * kMaxWavesPerCascade);
        const int cascade_count = std::min<int>(int(cascades.size()), kMaxCascades);
        int waves_per_cascade = 0;
        for (int c = 0; c < cascade_count; ++c) {
            const auto& waves = cascades[std::size_t(c)].waves;
            waves_per_cascade = std::min<int>(int(waves.size()), kMaxWavesPerCascade);
            for (int i = 0; i < waves_per_cascade; ++i) {
                const FbmWave& w = waves[std::size_t(i)];
                data[std::size_t(c * kMaxWavesPerCascade + i)] = {
                    {float(w.dx), float(w.dz), float(w.wavenumber), float(w.amplitude)},
                    {float(step01::phase_at(w.phase_rate, time)), 0, 0, 0}};
            }
        }
        ocean::buffer_sub_data(buffer_, 0, GLsizeiptr(data.size() * sizeof(GpuWave)), data.data());
        glBindBufferBase(GL_UNIFORM_BUFFER, 0, buffer_.id());
        program.set("u_cascade_count", cascade_count);
        program.set("u_waves_per_cascade", waves_per_cascade);
        program.set("u_warp", float(warp));
    }

private:
    struct GpuWave {
        std::array<float, 4> direction_wavenumber_amplitude;
        std::array<float, 4> phase;
    };
    static_assert(sizeof(GpuWave) == 32, "std140 stride of FbmWave");
    ocean::Buffer buffer_;
};

}  // namespace step04
