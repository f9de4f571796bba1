// Chapter 2's math: analytic derivatives against central differences, the normal from T and B,
// and the light terms against values worked out by hand.
#include "step03_lighting/lighting.hpp"
#include "step03_lighting/normals.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

const std::vector<step02::DirectionalWave> kWaves{
    {20, 18.0, 0.99, 5.3}, {87, 12.2, 0.67, 4.4}, {154, 8.3, 0.46, 3.6}, {221, 5.7, 0.31, 3.0}, {300, 1.3, 0.05, -1.4}};

TEST(Step03Normals, AnalyticDerivativesMatchCentralDifferences) {
    // Central differences with h = 1e-5 in double precision: truncation h^2 a w^3 / 6 < 1e-9;
    // rounding: sin of angles up to ~2000 rad is good to ~2e-13, divided by 2h gives ~1e-8.
    for (double t : {0.0, 1.5, 1000.25})
        for (double x : {-30.0, -2.2, 0.0, 7.9, 39.0})
            for (double z : {-25.0, 0.3, 18.0}) {
                const auto analytic = step03::height_and_gradient(kWaves, x, z, t);
                const auto numeric = step03::finite_difference_gradient(kWaves, x, z, t, 1e-5);
                EXPECT_NEAR(analytic.height, step02::height(kWaves, x, z, t), 1e-12);
                EXPECT_NEAR(analytic.dh_dx, numeric.dh_dx, 1e-7) << x << "," << z << " t=" << t;
                EXPECT_NEAR(analytic.dh_dz, numeric.dh_dz, 1e-7) << x << "," << z << " t=" << t;
            }
}

TEST(Step03Normals, NotesUnitStepIsOnlyApproximate) {
    // With the notes' step of 1 m, the slope of a 1.3 m wave is badly off: that is the point of
    // the comparison view.
    const std::vector<step02::DirectionalWave> short_wave{{0, 1.3, 0.05, 0}};
    const auto analytic = step03::height_and_gradient(short_wave, 0.1, 0, 0);
    const auto seed = step03::finite_difference_gradient(short_wave, 0.1, 0, 0, 1.0);
    EXPECT_GT(std::abs(analytic.dh_dx - seed.dh_dx), 0.1 * std::abs(analytic.dh_dx));
}

TEST(Step03Normals, NormalIsBitangentCrossTangent) {
    const auto g = step03::height_and_gradient(kWaves, 3.0, -4.0, 2.0);
    const auto n = step03::normal(g);
    const auto bxt = step03::normalize(step03::cross(step03::bitangent(g), step03::tangent(g)));
    EXPECT_NEAR(n.x, bxt.x, 1e-15);
    EXPECT_NEAR(n.y, bxt.y, 1e-15);
    EXPECT_NEAR(n.z, bxt.z, 1e-15);
    EXPECT_GT(n.y, 0) << "points up, out of the water";
    EXPECT_NEAR(step03::dot(n, step03::tangent(g)), 0, 1e-15);
    EXPECT_NEAR(step03::dot(n, step03::bitangent(g)), 0, 1e-15);
    // A slope rising towards +x tilts the normal towards -x.
    const auto tilted = step03::normal({0, 1.0, 0});
    EXPECT_NEAR(tilted.x, -std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(tilted.y, std::sqrt(0.5), 1e-15);
}

TEST(Step03Lighting, HandComputedTerms) {
    step03::Light light;
    light.to_sun = step03::sun_direction(0, 30);  // (cos 30, sin 30, 0)
    light.sun = {1, 1, 1};
    light.water = {0.1, 0.4, 0.8};
    light.ambient = {0.01, 0.02, 0.03};
    light.shininess = 2;
    const step03::Vec3 up{0, 1, 0};
    const step03::Vec3 eye = step03::normalize({-std::cos(0.5236), std::sin(0.5236), 0});  // mirror of L
    const auto t = step03::light_terms(up, eye, light);
    EXPECT_NEAR(t.diffuse.g, 0.4 * 0.5, 1e-12);    // N.L = sin 30
    EXPECT_NEAR(t.specular.r, 1.0, 1e-4);          // mirror direction: H = N, (N.H)^2 = 1
    EXPECT_DOUBLE_EQ(t.ambient.b, 0.03);
    // The notes' unnormalised H = V + L would give (N.H)^2 = (2 sin 30)^2 = 1 here too, but
    // (N.(V+L))^2 = 4 straight above: normalising keeps it at most 1.
    const auto above = step03::light_terms(up, up, {up, {1, 1, 1}, {0, 0, 0}, {0, 0, 0}, 2});
    EXPECT_NEAR(above.specular.r, 1.0, 1e-12);
}

TEST(Step03Lighting, NoLightFromBelowTheSurface) {
    step03::Light light{step03::sun_direction(0, -20), {1, 1, 1}, {0.2, 0.4, 0.6}, {0, 0, 0}, 8};
    const auto t = step03::light_terms({0, 1, 0}, step03::normalize({1, -0.2, 0}), light);
    EXPECT_EQ(t.diffuse.b, 0);
    EXPECT_EQ(t.specular.r, 0) << "no glint where the sun is behind the surface";
}

// Phong's glint (the step's specular=phong), held to the mirror it is made of and to Blinn-Phong's size.
TEST(Step03Lighting, PhongGlintsWhereTheEyeSeesTheSunMirrored) {
    step03::Light light;
    light.to_sun = step03::normalize({0.3, 0.8, -0.5});
    light.shininess = 160;
    const step03::Vec3 n = step03::normalize({-0.2, 1.0, 0.1});
    // The sun turned half a turn about the normal: where a mirror sends its light.
    const double c = step03::dot(n, light.to_sun);
    const step03::Vec3 across{light.to_sun.x - c * n.x, light.to_sun.y - c * n.y, light.to_sun.z - c * n.z};
    const step03::Vec3 mirror{c * n.x - across.x, c * n.y - across.y, c * n.z - across.z};
    EXPECT_NEAR(step03::phong_specular(n, mirror, light), 1.0, 1e-12);
    // No glint from a sun behind the surface, even seen from its mirror direction.
    const step03::Vec3 down{-n.x, -n.y, -n.z};
    EXPECT_EQ(step03::phong_specular(down, {-mirror.x, -mirror.y, -mirror.z}, light), 0.0);
}

TEST(Step03Lighting, PhongGlintIsAsWideAsBlinnPhongs) {
    // An eye turned away from the mirror direction, in the plane of N and L, to where Blinn-Phong's
    // glint falls to half: Phong's falls to half there too (within 1 %), at every shininess.
    for (double shininess : {64.0, 160.0, 2000.0}) {
        step03::Light light;
        light.sun = {1, 1, 1};
        light.shininess = shininess;
        const double incidence = 0.7;  // radians from the normal (0, 1, 0), in the x-y plane
        light.to_sun = {std::sin(incidence), std::cos(incidence), 0};
        const double half_angle = std::acos(std::pow(0.5, 1 / shininess));  // N from H where Blinn-Phong is 1/2
        const double eye_angle = -incidence + 2 * half_angle;  // the eye 2 x from the mirror direction
        const step03::Vec3 eye{std::sin(eye_angle), std::cos(eye_angle), 0};
        const step03::Vec3 up{0, 1, 0};
        EXPECT_NEAR(step03::light_terms(up, eye, light).specular.r, 0.5, 1e-9);
        EXPECT_NEAR(step03::phong_specular(up, eye, light), 0.5, 0.01) << "shininess " << shininess;
    }
}

}  // namespace
