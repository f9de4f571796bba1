// water.glsl on the GPU against its CPU reference in double (water_light.hpp, optics.hpp): the
// Fresnel reflectance from below, the water's own light along a path and the seabed's radiance,
// in the program's own water (set_water, the uniforms the frame binds), for clear and coastal
// water under a sun 45 and 20 degrees up. Each value within 1e-4 of the largest of its kind
// (float's exp and pow over paths of 40 m keep about 1e-5).
#include "common/constants.hpp"
#include "step10_underwater/optics.hpp"
#include "step10_underwater/underwater.hpp"
#include "step10_underwater/water_light.hpp"
#include "tests/gpu/full_screen_draw.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr int kColumns = 256;

struct WaterOnTheGpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

// Column i's eye, as eval_water.frag's eye_case.
void eye_case(int i, double& depth, glm::dvec3& d, double& t) {
    const double f = (i + 0.5) / kColumns;
    const auto fract = [](double x) { return x - std::floor(x); };
    depth = 20 * f;
    const double elevation = glm::radians(-90 + 150 * fract(7 * f)), azimuth = glm::radians(360 * fract(13 * f));
    d = {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
    t = 0.5 + 39.5 * fract(3 * f);
}

TEST_F(WaterOnTheGpu, WaterGlslIsItsCpuReference) {
    ocean::ShaderProgram* p = cache("eval_water", {"common/shaders/fullscreen.vert", "step10_underwater/tests/eval_water.frag"}, {});
    ASSERT_NE(p, nullptr);
    for (const char* water_name : {"clear_ocean", "coastal"})
        for (double sun_elevation : {45.0, 20.0}) {
            const step10::WaterType* water = step10::water_type_named(water_name);
            ASSERT_NE(water, nullptr);
            step06::LookParams look;
            look.sun_elevation = float(sun_elevation);
            const step10::WaterLight light = step10::water_light(*water, 12, glm::dvec3(0.6, 0.55, 0.4), look);
            step10::set_water(*p, light);
            p->set("u_columns", kColumns);
            const std::vector<float> gpu = ocean_test::draw_full_screen<float>(*p, kColumns, 3, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4);
            const auto at = [&](int x, int y, int c) { return double(gpu[(std::size_t(y) * kColumns + x) * 4 + c]); };
            double worst[3] = {0, 0, 0}, largest[3] = {1, 0, 0};
            std::vector<glm::dvec3> in_water(kColumns), bed(kColumns);
            for (int i = 0; i < kColumns; ++i) {
                const double f = (i + 0.5) / kColumns;
                worst[0] = std::max(worst[0], std::abs(at(i, 0, 0) - step10::reflectance_water_to_air(std::acos(f))));
                double depth, t;
                glm::dvec3 d;
                eye_case(i, depth, d, t);
                in_water[i] = step10::inscatter(light, depth, d, t);
                bed[i] = step10::seabed_radiance(light, 4 * f);
                for (int c = 0; c < 3; ++c) {
                    largest[1] = std::max(largest[1], in_water[i][c]);
                    largest[2] = std::max(largest[2], bed[i][c]);
                }
            }
            for (int i = 0; i < kColumns; ++i)
                for (int c = 0; c < 3; ++c) {
                    worst[1] = std::max(worst[1], std::abs(at(i, 1, c) - in_water[i][c]));
                    worst[2] = std::max(worst[2], std::abs(at(i, 2, c) - bed[i][c]));
                }
            std::printf("%s, sun %2.0f deg: worst over the largest: Fresnel %.1e, in-scattering %.1e (of %.3g), "
                        "seabed %.1e (of %.3g)\n", water_name, sun_elevation, worst[0], worst[1] / largest[1], largest[1],
                        worst[2] / largest[2], largest[2]);
            EXPECT_LT(worst[0], 1e-4) << water_name << ", sun " << sun_elevation;
            EXPECT_LT(worst[1] / largest[1], 1e-4) << water_name << ", sun " << sun_elevation;
            EXPECT_LT(worst[2] / largest[2], 1e-4) << water_name << ", sun " << sun_elevation;
        }
}

}  // namespace
