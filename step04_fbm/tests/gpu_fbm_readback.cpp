// step04 on the GPU against its CPU reference: positions and exact normals of the warped fBm
// cascades, captured from the real ocean.vert, for the three wave shapes.
// Tolerances: heights 1e-4 m (a sum of 2 x 48 single-precision terms, amplitudes <= 1.2 m),
// normals 2e-3 (wave 47 is 1.7 cm long: single-precision angles reach 15000 rad at 40 m).
#include "common/grid.hpp"
#include "step04_fbm/fbm_uniforms.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/vertex_capture.hpp"

namespace {

using FbmReadback = ocean_test::GlTest;

TEST_F(FbmReadback, WarpedCascadesMatchTheCpu) {
    step04::CascadeSettings s;
    s.wave_count = 48;
    s.base_amplitude = 1.2;
    const auto cascades = step04::make_cascades(s, 2, 0.37);
    ocean::GridMesh grid;
    const int quads = 32;
    grid.build({80.0f, 80.0f}, quads, quads);
    const auto rest = ocean::grid_positions({80.0f, 80.0f}, quads, quads);
    step04::FbmUniforms uniforms;

    for (int shape : {0, 1, 2}) {
        ocean::ShaderProgram program("ocean", {OCEAN_SOURCE_DIR "/step04_fbm/shaders/ocean.vert"},
                                     {"v_world_position", "v_normal"}, {"SHAPE " + std::to_string(shape)});
        ASSERT_FALSE(program.build()) << program.last_error();
        for (double warp : {0.0, 2.0})
            for (double t : {0.0, 1.5, 3600.5}) {
                uniforms.upload(program, cascades, warp, t);
                program.set("u_view_projection", glm::mat4(1.0f));
                const auto out = ocean_test::capture_vertices(program, grid, 6);
                double worst_height = 0, worst_normal = 0;
                for (std::size_t i = 0; i < rest.size(); ++i) {
                    const float* v = &out[i * 6];
                    const auto g = step04::height_gradient(cascades, step04::Shape(shape), warp, rest[i].x,
                                                           rest[i].y, t);
                    const auto n = step03::normal(g);
                    worst_height = std::max(worst_height, std::abs(v[1] - g.height));
                    worst_normal = std::max({worst_normal, std::abs(v[3] - n.x), std::abs(v[4] - n.y),
                                             std::abs(v[5] - n.z)});
                }
                std::printf("shape %d, warp %.1f, t = %g: worst height error %.2e m, worst normal error %.2e\n",
                            shape, warp, t, worst_height, worst_normal);
                EXPECT_LT(worst_height, 1e-4);
                EXPECT_LT(worst_normal, 2e-3);
            }
    }
}

}  // namespace
