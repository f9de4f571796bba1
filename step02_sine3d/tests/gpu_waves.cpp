// The GPU's waves against the CPU reference in double precision.
//  - step01: sine_sum.glsl evaluated by a compute shader into a buffer.
//  - step02: the positions ocean.vert outputs, captured by transform feedback from the real
//    vertex shader, fed by the real grid and the real uniform upload.
// Tolerance 1e-4 m: float sin() of arguments up to ~60 rad has an absolute error near 1e-5.
#include "common/grid.hpp"
#include "common/shader.hpp"
#include "step01_sine2d/sine_sum.hpp"
#include "step02_sine3d/wave_uniforms.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/vertex_capture.hpp"

#include <cmath>
#include <cstring>

namespace {

using WaveReadback = ocean_test::GlTest;

const std::string kSource = OCEAN_SOURCE_DIR;


TEST_F(WaveReadback, Step02DisplacedVerticesMatchTheCpu) {
    ocean::ShaderProgram program("ocean", {kSource + "/step02_sine3d/shaders/ocean.vert"}, {"v_world_position"});
    ASSERT_FALSE(program.build()) << program.last_error();
    const std::vector<step02::DirectionalWave> waves{
        {20, 18.0, 0.99, 5.3}, {87, 12.2, 0.67, 4.4}, {154, 8.3, 0.46, 3.6}, {221, 5.7, 0.31, 3.0},
        {300, 1.3, 0.05, -1.4}};
    ocean::GridMesh grid;
    const int quads = 48;
    grid.build({80.0f, 60.0f}, quads, quads);
    const auto rest = ocean::grid_positions({80.0f, 60.0f}, quads, quads);
    ASSERT_EQ(int(rest.size()), grid.vertex_count());

    for (double t : {0.0, 1.5, 12.75, 3600.0}) {
        step02::upload_waves(program, waves, t);
        program.set("u_view_projection", glm::mat4(1.0f));
        const auto captured = ocean_test::capture_vertices(program, grid, 3);
        std::vector<glm::vec3> positions(rest.size());
        std::memcpy(positions.data(), captured.data(), captured.size() * sizeof(float));
        double worst = 0;
        for (std::size_t i = 0; i < rest.size(); ++i) {
            ASSERT_EQ(positions[i].x, rest[i].x);
            ASSERT_EQ(positions[i].z, rest[i].y);
            const double expected = step02::height(waves, rest[i].x, rest[i].y, t);
            worst = std::max(worst, std::abs(double(positions[i].y) - expected));
        }
        EXPECT_LT(worst, 1e-4) << "t = " << t;
    }
}

}  // namespace
