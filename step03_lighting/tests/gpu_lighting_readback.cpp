// step03 on the GPU against its CPU reference: positions, normals (analytic and finite
// difference) and the per-vertex lit colour, captured from the real ocean.vert.
// Tolerance 1e-3 on normals and colours: single-precision sin/cos/pow of arguments up to ~60 rad.
#include "common/grid.hpp"
#include "step02_sine3d/wave_uniforms.hpp"
#include "step03_lighting/light_uniforms.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/vertex_capture.hpp"

namespace {

using LightingReadback = ocean_test::GlTest;

TEST_F(LightingReadback, NormalsAndPerVertexLightMatchTheCpu) {
    const std::vector<step02::DirectionalWave> waves{
        {20, 18.0, 0.99, 5.3}, {87, 12.2, 0.67, 4.4}, {154, 8.3, 0.46, 3.6}, {221, 5.7, 0.31, 3.0},
        {300, 1.3, 0.05, -1.4}};
    const step03::Light light{step03::sun_direction(305, 25), {1.0, 0.9, 0.8}, {0.1, 0.4, 0.7},
                              {0.02, 0.05, 0.1}, 32};
    const glm::vec3 eye(-30.0f, 25.0f, 40.0f);
    ocean::GridMesh grid;
    const int quads = 40;
    grid.build({80.0f, 80.0f}, quads, quads);
    const auto rest = ocean::grid_positions({80.0f, 80.0f}, quads, quads);

    for (int method : {0, 1})
        for (double t : {0.0, 1.5, 700.125}) {
            // The step's per-vertex, lit variant with this normal method.
            ocean::ShaderProgram program("ocean", {OCEAN_SOURCE_DIR "/step03_lighting/shaders/ocean.vert"},
                                         {"v_world_position", "v_normal", "v_vertex_colour"},
                                         {"NORMAL_METHOD " + std::to_string(method), "VIEW 0", "PER_PIXEL 0"});
            ASSERT_FALSE(program.build()) << program.last_error();
            step02::upload_waves(program, waves, t);
            step03::upload_light(program, light);
            program.set("u_view_projection", glm::mat4(1.0f));
            program.set("u_eye", eye);
            program.set("u_fd_step", 0.5f);
            const auto out = ocean_test::capture_vertices(program, grid, 9);
            double worst_normal = 0, worst_colour = 0;
            for (std::size_t i = 0; i < rest.size(); ++i) {
                const float* v = &out[i * 9];
                const double x = rest[i].x, z = rest[i].y;
                const auto g = method == 0 ? step03::height_and_gradient(waves, x, z, t)
                                           : step03::finite_difference_gradient(waves, x, z, t, 0.5);
                const auto n = step03::normal(g);
                worst_normal = std::max({worst_normal, std::abs(v[3] - n.x), std::abs(v[4] - n.y), std::abs(v[5] - n.z)});
                const step03::Vec3 position{x, g.height, z};
                const auto to_eye = step03::normalize({eye.x - position.x, eye.y - position.y, eye.z - position.z});
                const auto c = step03::lit_colour(step03::light_terms(n, to_eye, light));
                worst_colour = std::max({worst_colour, std::abs(v[6] - c.r), std::abs(v[7] - c.g), std::abs(v[8] - c.b)});
            }
            EXPECT_LT(worst_normal, 1e-3) << "method " << method << ", t = " << t;
            EXPECT_LT(worst_colour, 1e-3) << "method " << method << ", t = " << t;
            std::printf("method %d, t = %g: worst normal error %.2e, worst colour error %.2e\n", method, t,
                        worst_normal, worst_colour);
        }
}

}  // namespace

namespace {

// The step builds a variant per choice of normals, view and lighting (surface.glsl): all 24 build.
TEST_F(LightingReadback, EveryVariantBuilds) {
    const std::string dir = OCEAN_SOURCE_DIR "/step03_lighting/shaders/";
    for (int method = 0; method < 2; ++method)
        for (int view = 0; view < 6; ++view)
            for (int per_pixel = 0; per_pixel < 2; ++per_pixel) {
                ocean::ShaderProgram program("ocean", {dir + "ocean.vert", dir + "ocean.frag"}, {},
                                             {"NORMAL_METHOD " + std::to_string(method), "VIEW " + std::to_string(view),
                                              "PER_PIXEL " + std::to_string(per_pixel)});
                EXPECT_FALSE(program.build()) << method << " " << view << " " << per_pixel << ": "
                                              << program.last_error();
            }
}

}  // namespace
