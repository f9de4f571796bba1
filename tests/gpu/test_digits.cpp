// common/shaders/digits.glsl on the GPU (step01's axis numbers, the map views' legends).
#include "common/gl.hpp"
#include "common/shader.hpp"
#include "tests/gpu/gl_test_context.hpp"

#include <string>
#include <vector>

namespace {

// common/shaders/digits.glsl, which numbers step01's axes and the map views' legends: each digit
// lights the segments a seven-segment display lights (the table below, written as letters, is
// the usual one, not the shader's bit masks), and no others; '-' is g alone; "-12.5" is laid out
// with its minus and its point where they belong; nothing is drawn far from a label.
TEST(DigitsGlsl, EachDigitLightsItsSegments) {
    ocean::ShaderProgram program("eval_digits", {std::string(OCEAN_SOURCE_DIR) + "/tests/gpu/shaders/eval_digits.comp"});
    ASSERT_FALSE(program.build()) << program.last_error();
    ocean::Buffer out = ocean::make_buffer();
    glNamedBufferStorage(out.id(), GLsizeiptr(90 * sizeof(float)), nullptr, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.id());
    glUseProgram(program.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> coverage(90);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(coverage.size() * sizeof(float)), coverage.data());
    const char* lit[11] = {"abcdef", "bc", "abdeg", "abcdg", "bcfg", "acdfg", "acdefg", "abc", "abcdefg", "abcdfg", "g"};
    for (int d = 0; d < 11; ++d)
        for (int s = 0; s < 7; ++s) {
            const bool on = std::string(lit[d]).find(char('a' + s)) != std::string::npos;
            EXPECT_NEAR(coverage[std::size_t(d * 7 + s)], on ? 1.0 : 0.0, 1e-6) << "glyph " << d << ", segment " << char('a' + s);
        }
    const float layout[6] = {1, 1, 0, 1, 0, 0};  // '-', '.', no top on '.', '5' f, not '5' b, far away
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(coverage[std::size_t(84 + i)], layout[i], 1e-6) << "layout probe " << i;
}

}  // namespace
