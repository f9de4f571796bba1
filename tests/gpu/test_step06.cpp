// step06 on the GPU: foam decay at two frame rates, tessellation (primitive counts against the
// CPU level, culling behind the camera), and the sky cubemap (the sun's texel, an image sky,
// missing and corrupt files).
#include "common/image.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/patch_grid.hpp"
#include "step06_foam_sky/sky.hpp"
#include "step06_foam_sky/tessellation.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

struct Step06Gpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    ocean::ProgramFactory factory() { return cache.factory(); }
    // A calm sea (all maps zero, J = 1) of 4 cascades at N = 64.
    std::vector<step05::InitialSpectrum> calm = std::vector<step05::InitialSpectrum>(4);
    std::unique_ptr<step05::GpuOcean> calm_ocean() {
        step05::SpectrumParams p;
        p.resolution = 64;
        p.wind_speed = 0;
        std::vector<const step05::InitialSpectrum*> pointers;
        for (auto& s : calm) {
            s = step05::initial_spectrum(p);
            pointers.push_back(&s);
        }
        auto ocean = std::make_unique<step05::GpuOcean>(factory());
        ocean->set_spectra(pointers);
        ocean::GpuTimers timers;
        ocean->simulate(0, step05::Backend::GpuFft, 1, timers);
        return ocean;
    }
};

TEST_F(Step06Gpu, FoamImpulseDecaysAsExpOfRateTimesTimeAtAnyFrameRate) {
    const auto ocean = calm_ocean();
    step06::FoamSettings settings;
    settings.decay_rate = 1.3;
    for (double dt : {1.0 / 30, 1.0 / 120}) {
        step06::FoamSimulation foam(factory());
        foam.resize(64, 4);
        foam.fill(1.0f);
        for (int i = 0; i < int(std::lround(1 / dt)); ++i) foam.update(*ocean, dt, settings, {1, 1, 1, 1});
        const auto values = foam.read_layer(2);
        const double expected = std::exp(-1.3);
        for (float v : values) ASSERT_NEAR(v / expected, 1.0, 0.01) << "dt = " << dt;
        std::printf("foam after 1 s at dt = 1/%d: %.6f, exp(-1.3) = %.6f\n", int(std::lround(1 / dt)), values[0],
                    expected);
    }
}

struct Tessellated : Step06Gpu {
    std::unique_ptr<step05::GpuOcean> ocean = calm_ocean();
    ocean::ShaderProgram* program = nullptr;
    void SetUp() override {
        Step06Gpu::SetUp();
        const std::string dir = "step06_foam_sky/shaders/";
        program = cache("ocean", {dir + "ocean.vert", dir + "ocean.tesc", dir + "ocean.tese", dir + "ocean.frag"}, {});
        ASSERT_NE(program, nullptr);
    }
    // Triangles the tessellator makes for one 16 m patch at the origin, seen from `eye`.
    long triangles(glm::vec3 eye, glm::vec3 target, float tess_scale) {
        step06::PatchGrid grid;
        grid.build(1, 16);
        const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 5000.0f) *
                             glm::lookAt(eye, target, std::abs(target.x - eye.x) + std::abs(target.z - eye.z) < 1e-3f
                                                          ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0));
        program->set("u_view_projection", vp);
        program->set("u_eye", eye);
        program->set("u_grid_offset", glm::vec2(0));
        program->set("u_patch_size", 16.0f);
        program->set("u_tess_scale", tess_scale);
        program->set("u_frustum", step06::frustum_planes(vp));
        program->set("u_max_displacement", 1.0f);
        program->set("u_cull", 1);
        program->set("u_patch_sizes", std::vector<float>{500, 137, 41, 12});
        glBindTextureUnit(0, ocean->displacement_texture());
        glBindTextureUnit(1, ocean->slopes_texture());
        program->set("u_displacement", 0);
        program->set("u_slopes", 1);
        program->set("u_foam", 2);  // samplers of different types may not share a unit
        program->set("u_sky", 3);
        ocean::Query query = ocean::make_query(GL_PRIMITIVES_GENERATED);
        glUseProgram(program->id());
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginQuery(GL_PRIMITIVES_GENERATED, query.id());
        grid.draw();
        glEndQuery(GL_PRIMITIVES_GENERATED);
        glDisable(GL_RASTERIZER_DISCARD);
        GLuint64 count = 0;
        glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &count);
        return long(count);
    }
};

TEST_F(Tessellated, LevelFallsWithDistanceAsTheCpuFormulaSays) {
    long previous = 1L << 40;
    for (float height : {20.0f, 60.0f, 200.0f, 800.0f}) {
        // Straight above the patch centre every edge midpoint is at the same distance.
        const glm::vec3 eye(0, height, 0);
        const double distance = std::sqrt(double(height) * height + 64.0);  // to an edge midpoint, 8 m off
        const long expected = step06::triangles_for_uniform_level(step06::tessellation_level(distance, 16, 12));
        const long got = triangles(eye, glm::vec3(0, 0, 0), 12);
        EXPECT_EQ(got, expected) << "height " << height;
        EXPECT_LE(got, previous);
        previous = got;
        std::printf("eye %4.0f m above: %ld triangles (CPU: %ld)\n", double(height), got, expected);
    }
}

TEST_F(Tessellated, PatchesBehindTheCameraAreCulled) {
    const long in_front = triangles({0, 5, 40}, {0, 0, 0}, 12);
    const long behind = triangles({0, 5, 40}, {0, 0, 100}, 12);
    EXPECT_GT(in_front, 0);
    EXPECT_EQ(behind, 0) << "a patch behind the camera makes no triangles";
}

// The brightest texel of the cubemap, as a direction.
glm::vec3 brightest_direction(const step06::Sky& sky) {
    const int size = sky.size();
    std::vector<float> texels(std::size_t(size) * size * 6 * 4);
    glGetTextureImage(sky.cubemap(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    std::size_t best = 0;
    float best_luminance = -1;
    for (std::size_t i = 0; i < texels.size() / 4; ++i) {
        const float l = 0.2126f * texels[4 * i] + 0.7152f * texels[4 * i + 1] + 0.0722f * texels[4 * i + 2];
        if (l > best_luminance) { best_luminance = l; best = i; }
    }
    const int face = int(best / (std::size_t(size) * size));
    const int y = int(best / std::size_t(size)) % size, x = int(best % std::size_t(size));
    return step06::cube_texel_direction(face, x, y, size);
}

float degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

TEST_F(Step06Gpu, BrightestSkyTexelIsTheSun) {
    step06::Sky sky(factory(), 64);
    for (glm::vec3 sun : {glm::vec3(0.3f, 0.4f, -0.8f), glm::vec3(-0.9f, 0.15f, 0.2f), glm::vec3(0.1f, 0.95f, 0.2f)}) {
        step06::SkySettings s;
        s.to_sun = glm::normalize(sun);
        sky.render(s);
        const float error = degrees_between(brightest_direction(sky), s.to_sun);
        EXPECT_LT(error, 2.0f) << "one texel of 64 is ~1.4 degrees";
        std::printf("sun (%.2f, %.2f, %.2f): brightest texel %.2f degrees away\n", s.to_sun.x, s.to_sun.y, s.to_sun.z,
                    double(error));
    }
}

TEST_F(Step06Gpu, SkyFromAnImageAndItsFailures) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("ocean_sky_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // A 64 x 32 equirectangular image, grey with one bright spot at longitude 90 degrees (+z),
    // latitude 30 degrees up: column 48, row 10 of 32 (row 0 is straight up).
    ocean::Image image{64, 32, std::vector<std::uint8_t>(64 * 32 * 4, 60)};
    for (int y = 9; y <= 10; ++y)
        for (int x = 47; x <= 48; ++x) {
            std::uint8_t* p = &image.rgba[(std::size_t(y) * 64 + std::size_t(x)) * 4];
            p[0] = p[1] = p[2] = 255;
        }
    ASSERT_FALSE(ocean::save_png(image, (dir / "spot.png").string()));
    step06::Sky sky(factory(), 64);
    EXPECT_FALSE(sky.use_image((dir / "spot.png").string()));
    EXPECT_TRUE(sky.uses_image());
    sky.render({});
    const glm::vec3 expected(0, std::sin(glm::radians(30.0f)), std::cos(glm::radians(30.0f)));
    EXPECT_LT(degrees_between(brightest_direction(sky), expected), 8.0f) << "a texel of the image is 5.6 degrees";

    const auto missing = sky.use_image((dir / "missing.hdr").string());
    ASSERT_TRUE(missing);
    EXPECT_NE(missing->find("procedural"), std::string::npos) << *missing;
    EXPECT_FALSE(sky.uses_image());
    std::ofstream(dir / "corrupt.png") << "\x89PNG\r\n\x1a\n not an image at all";
    const auto corrupt = sky.use_image((dir / "corrupt.png").string());
    ASSERT_TRUE(corrupt);
    EXPECT_NE(corrupt->find("not a readable image"), std::string::npos) << *corrupt;
    EXPECT_FALSE(sky.uses_image());
    sky.render({});  // back on the procedural sky, without a GL error
    fs::remove_all(dir);
}

}  // namespace
