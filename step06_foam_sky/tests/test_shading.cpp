// step06's light on water (shading.hpp) against what holds outside the code: the Fresnel
// equations' closed forms, the microfacet distributions' normalisation, Smith's masking at normal
// incidence, and how far Schlick's curve strays from the exact reflectance of water.
#include "step06_foam_sky/shading.hpp"

#include <gtest/gtest.h>

namespace {

using step06::Microfacet;

TEST(Step06Fresnel, ExactReflectanceHasItsClosedFormsAndSchlickFollowsIt) {
    const double n = step06::kWaterIndex;
    const double f0 = step06::normal_incidence_reflectance(n);
    EXPECT_NEAR(f0, 0.0204, 1e-4);  // ((1.333 - 1) / 2.333)^2: the 0.02 the renderer uses
    EXPECT_NEAR(step06::fresnel_dielectric(1.0, n), f0, 1e-12);
    EXPECT_NEAR(step06::fresnel_dielectric(0.0, n), 1.0, 1e-12);  // grazing: a mirror
    // Brewster's angle, tan(theta_B) = n: the p reflectance vanishes, so F = rs^2 / 2.
    const double brewster = std::atan(n), ci = std::cos(brewster), ct = std::sqrt(1 - std::pow(std::sin(brewster) / n, 2));
    const double rs = (ci - n * ct) / (ci + n * ct);
    EXPECT_NEAR(step06::fresnel_dielectric(ci, n), 0.5 * rs * rs, 1e-12);
    double worst = 0, previous = 0;
    for (int i = 0; i <= 900; ++i) {  // 0 to 90 degrees from the normal
        const double c = std::cos(ocean::kPi / 2 * i / 900.0);
        const double exact = step06::fresnel_dielectric(c, n), schlick = step06::fresnel_schlick(c, f0);
        worst = std::max(worst, std::abs(exact - schlick));
        EXPECT_GE(exact, previous - 1e-12) << "reflectance grows towards grazing";
        previous = exact;
    }
    // Schlick is worst near grazing, where water's exact curve rises later (measured 0.059 at
    // about 84 degrees): the renderer's choice costs that much of the sky's reflection there.
    std::printf("water: F0 = %.4f, Schlick's worst error against the exact Fresnel %.4f\n", f0, worst);
    EXPECT_LT(worst, 0.065);
}

TEST(Step06Microfacet, DistributionsIntegrateToOneAndMaskingVanishesHeadOn) {
    for (Microfacet m : {Microfacet::Ggx, Microfacet::Beckmann})
        for (double alpha : {0.05, 0.2, 0.6}) {
            // Integral over the hemisphere of D(h) cos(theta_h) d omega = 2 pi int D cos sin d theta.
            const int steps = 200000;
            double integral = 0;
            for (int i = 0; i < steps; ++i) {
                const double theta = (i + 0.5) / steps * ocean::kPi / 2;
                integral += step06::microfacet_distribution(std::cos(theta), alpha, m) * std::cos(theta) * std::sin(theta);
            }
            integral *= 2 * ocean::kPi * (ocean::kPi / 2) / steps;
            EXPECT_NEAR(integral, 1.0, 2e-3) << (m == Microfacet::Ggx ? "GGX" : "Beckmann") << " alpha " << alpha;
            EXPECT_NEAR(step06::smith_lambda(1.0, alpha, m), 0.0, 1e-9);  // seen head-on, nothing is masked
            // Masking grows towards grazing (for a smooth surface only very near it: Beckmann's
            // fit is exactly 0 until alpha tan(theta) passes 1 / 1.6).
            EXPECT_GT(step06::smith_lambda(0.01, alpha, m), step06::smith_lambda(0.7, alpha, m));
            EXPECT_GE(step06::smith_lambda(0.1, alpha, m), step06::smith_lambda(0.7, alpha, m));
        }
}

TEST(Step06Specular, NothingFromASunOrAnEyeBelowTheSurface) {
    const step03::Vec3 up{0, 1, 0}, eye = step03::normalize({0.3, 0.8, 0.1});
    EXPECT_EQ(step06::specular_factor(up, eye, step03::normalize({0.2, -0.1, 0.3}), 0.1, 0.02, Microfacet::Ggx), 0.0);
    EXPECT_EQ(step06::specular_factor(up, step03::normalize({0.2, -0.1, 0.3}), eye, 0.1, 0.02, Microfacet::Ggx), 0.0);
    // The mirror direction gets the peak of D: more than any other sun direction nearby.
    const step03::Vec3 mirror{-eye.x, eye.y, -eye.z}, beside = step03::normalize({-eye.x + 0.2, eye.y, -eye.z});
    EXPECT_GT(step06::specular_factor(up, eye, mirror, 0.1, 0.02, Microfacet::Ggx),
              step06::specular_factor(up, eye, beside, 0.1, 0.02, Microfacet::Ggx));
}

}  // namespace
