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

// The anisotropic distributions: still normalised; Beckmann's slopes have variance along^2 / 2
// along the wind and across^2 / 2 across it, whatever the wind's heading (the glitter's ellipse
// turns with the wind); equal alphas give back the isotropic D and Lambda.
TEST(Step06Microfacet, AnisotropicSlopesSpreadAlongTheWindAsTheirAlphasSay) {
    const step03::Vec3 up{0, 1, 0};
    for (double heading_degrees : {0.0, 40.0, 215.0}) {
        const double heading = heading_degrees * ocean::kPi / 180;
        const step06::Roughness r{0.3, 0.12, std::cos(heading), std::sin(heading)};
        for (Microfacet m : {Microfacet::Ggx, Microfacet::Beckmann}) {
            // Integral over the hemisphere of D(h) cos(theta_h) d omega.
            const int thetas = 4000, phis = 360;
            double integral = 0;
            for (int i = 0; i < thetas; ++i)
                for (int j = 0; j < phis; ++j) {
                    const double theta = (i + 0.5) / thetas * ocean::kPi / 2, phi = (j + 0.5) / phis * 2 * ocean::kPi;
                    const step03::Vec3 h{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
                    integral += step06::anisotropic_distribution(up, h, r, m) * std::cos(theta) * std::sin(theta);
                }
            integral *= (ocean::kPi / 2 / thetas) * (2 * ocean::kPi / phis);
            EXPECT_NEAR(integral, 1.0, 2e-3) << (m == Microfacet::Ggx ? "GGX" : "Beckmann") << ", heading " << heading_degrees;
        }
        // Beckmann's slopes (s_x, s_z): the facet normal is (-s_x, 1, -s_z) / |.|, and D cos^4 is their density.
        const double extent = 2.0, step = 0.004;
        double along2 = 0, across2 = 0, along_across = 0;
        for (double sx = -extent + step / 2; sx < extent; sx += step)
            for (double sz = -extent + step / 2; sz < extent; sz += step) {
                const double cos_beta = 1 / std::sqrt(1 + sx * sx + sz * sz);
                const step03::Vec3 h{-sx * cos_beta, cos_beta, -sz * cos_beta};
                const double density = step06::anisotropic_distribution(up, h, r, Microfacet::Beckmann) *
                                       cos_beta * cos_beta * cos_beta * cos_beta * step * step;
                const double su = sx * r.wind_x + sz * r.wind_z, sc = -sx * r.wind_z + sz * r.wind_x;
                along2 += density * su * su;
                across2 += density * sc * sc;
                along_across += density * su * sc;
            }
        EXPECT_NEAR(along2, r.along * r.along / 2, 1e-4) << "heading " << heading_degrees;
        EXPECT_NEAR(across2, r.across * r.across / 2, 1e-4) << "heading " << heading_degrees;
        EXPECT_NEAR(along_across, 0.0, 1e-5) << "the ellipse's axes are the wind's, heading " << heading_degrees;
    }
    // Equal alphas: the isotropic D and Lambda, from any heading.
    const step03::Vec3 n = step03::normalize({0.2, 0.9, -0.1}), h = step03::normalize({-0.3, 0.8, 0.25}),
                       w = step03::normalize({0.7, 0.3, 0.2});
    for (Microfacet m : {Microfacet::Ggx, Microfacet::Beckmann}) {
        const step06::Roughness r{0.2, 0.2, 0.6, 0.8};
        EXPECT_NEAR(step06::anisotropic_distribution(n, h, r, m), step06::microfacet_distribution(step03::dot(n, h), 0.2, m), 1e-12);
        EXPECT_NEAR(step06::anisotropic_lambda(n, w, r, m), step06::smith_lambda(step03::dot(n, w), 0.2, m), 1e-12);
    }
    // The masking of a direction grazing along the wind is the rougher one's.
    const step06::Roughness windy{0.4, 0.1, 1, 0};
    const step03::Vec3 along_wind = step03::normalize({1, 0.2, 0}), across_wind = step03::normalize({0, 0.2, 1});
    EXPECT_GT(step06::anisotropic_lambda(up, along_wind, windy, Microfacet::Ggx),
              step06::anisotropic_lambda(up, across_wind, windy, Microfacet::Ggx));
}

TEST(Step06Specular, NothingFromASunOrAnEyeBelowTheSurface) {
    const step03::Vec3 up{0, 1, 0}, eye = step03::normalize({0.3, 0.8, 0.1});
    const step06::Roughness r = step06::isotropic(0.1);
    EXPECT_EQ(step06::specular_factor(up, eye, step03::normalize({0.2, -0.1, 0.3}), r, 0.02, Microfacet::Ggx), 0.0);
    EXPECT_EQ(step06::specular_factor(up, step03::normalize({0.2, -0.1, 0.3}), eye, r, 0.02, Microfacet::Ggx), 0.0);
    // The mirror direction gets the peak of D: more than any other sun direction nearby.
    const step03::Vec3 mirror{-eye.x, eye.y, -eye.z}, beside = step03::normalize({-eye.x + 0.2, eye.y, -eye.z});
    EXPECT_GT(step06::specular_factor(up, eye, mirror, r, 0.02, Microfacet::Ggx),
              step06::specular_factor(up, eye, beside, r, 0.02, Microfacet::Ggx));
}

}  // namespace
