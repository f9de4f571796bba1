// The GPU's waves against the CPU reference in double precision: sine_sum.glsl evaluated by a
// compute shader into a buffer.
// Tolerance 1e-4 m: float sin() of arguments up to ~60 rad has an absolute error near 1e-5.
#include "common/shader.hpp"
#include "step01_sine2d/sine_sum.hpp"
#include "tests/gpu/gl_test_context.hpp"

#include <cmath>
#include <cstring>

namespace {

using WaveReadback = ocean_test::GlTest;

const std::string kSource = OCEAN_SOURCE_DIR;

TEST_F(WaveReadback, Step01SumOfSinesMatchesTheCpu) {
    ocean::ShaderProgram program("eval", {kSource + "/step01_sine2d/tests/eval_sine_sum.comp"});
    ASSERT_FALSE(program.build()) << program.last_error();
    const std::vector<step01::Wave> waves{{9.0, 0.8, 3.7}, {5.6, 0.48, -2.9}, {3.5, 0.29, 2.3},
                                          {0.7, 0.05, 1.0}};
    constexpr int kSamples = 1024;
    ocean::Buffer out = ocean::make_buffer();
    glNamedBufferStorage(out.id(), kSamples * sizeof(float) * 2, nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.id());
    for (double t : {0.0, 1.5, 37.25, 86400.0 * 3 + 0.1}) {
        std::vector<glm::vec4> packed;
        for (const auto& w : waves)
            packed.emplace_back(float(step01::angular_wavenumber(w)), float(w.amplitude),
                                float(step01::phase_at(step01::phase_rate(w), t)), 0.0f);
        program.set("u_wave_count", int(waves.size()));
        program.set("u_waves", packed);
        program.set("u_x_range", glm::vec2(-20.0f, 20.0f));
        program.set("u_sample_count", kSamples);
        glUseProgram(program.id());
        glDispatchCompute(kSamples / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<float> result(kSamples * 2);
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(result.size() * sizeof(float)), result.data());
        double worst = 0;
        for (int i = 0; i < kSamples; ++i) {
            const double x = -20.0 + 40.0 * i / (kSamples - 1);
            ASSERT_NEAR(result[2 * i], x, 1e-5);
            worst = std::max(worst, std::abs(result[2 * i + 1] - step01::sum_of_sines(waves, double(result[2 * i]), t)));
        }
        EXPECT_LT(worst, 1e-4) << "t = " << t;
    }
}

}  // namespace
