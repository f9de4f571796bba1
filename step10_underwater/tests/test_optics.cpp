// The chapter's optics held to what lies outside the code: closed forms from the Fresnel
// equations and Snell's law, published water data, and conservation of the light itself.
#include "common/constants.hpp"
#include "step10_underwater/caustics_reference.hpp"
#include "step10_underwater/lens.hpp"
#include "step10_underwater/optics.hpp"
#include "step10_underwater/water_colour.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

namespace {

using step10::kWaterIndex;
constexpr double kDegree = ocean::kPi / 180;

// The ray going up through still water at `angle` from the vertical, and the surface's normal.
glm::dvec3 upward_at(double angle) { return {std::sin(angle), std::cos(angle), 0}; }
const glm::dvec3 kUp{0, 1, 0};

TEST(Step10Optics, NormalIncidenceTransmitsOneMinusTheSquaredIndexRatio) {
    // Fresnel at normal incidence, both ways: R = ((n - 1) / (n + 1))^2, 2.04 % for water.
    const double r0 = std::pow((kWaterIndex - 1) / (kWaterIndex + 1), 2);
    EXPECT_NEAR(step10::transmittance_water_to_air(0), 1 - r0, 1e-12);
    EXPECT_NEAR(step10::fresnel_reflectance(0, 1.0, kWaterIndex), r0, 1e-12);
    EXPECT_NEAR(step10::transmittance_water_to_air(0), 0.980, 5e-4);
}

TEST(Step10Optics, CriticalAngleIs48Point6Degrees) {
    EXPECT_NEAR(step10::critical_angle(), std::asin(1 / kWaterIndex), 1e-15);
    EXPECT_NEAR(step10::critical_angle() / kDegree, 48.6, 0.05);
}

TEST(Step10Optics, ReflectanceRisesToOneAtTheCriticalAngle) {
    // Transmission falls as the angle grows and vanishes at the critical angle (like the square
    // root of the distance to it, so 1e-10 rad short of it leaves about 1e-4).
    const double critical = step10::critical_angle();
    double previous = 1;
    for (double angle = 0; angle < critical; angle += critical / 200) {
        const double t = step10::transmittance_water_to_air(angle);
        EXPECT_LE(t, previous + 1e-15) << angle / kDegree << " deg";
        previous = t;
    }
    EXPECT_GT(step10::reflectance_water_to_air(critical - 1e-10), 0.999);
    EXPECT_NEAR(step10::transmittance_water_to_air(critical - 1e-10), 0, 1e-3);
    EXPECT_GT(step10::transmittance_water_to_air(critical - 0.1), 0.5);  // still mostly through 6 deg short
}

TEST(Step10Optics, TotalInternalReflectionPastTheCriticalAngle) {
    const double critical = step10::critical_angle();
    EXPECT_TRUE(step10::refract_water_to_air(upward_at(critical - 1e-6), kUp).has_value());
    for (double angle : {critical + 1e-6, critical + 0.1, 80 * kDegree}) {
        EXPECT_FALSE(step10::refract_water_to_air(upward_at(angle), kUp).has_value()) << angle / kDegree;
        EXPECT_EQ(step10::reflectance_water_to_air(angle), 1.0);
    }
    // Just inside the critical angle the ray leaves skimming the surface (90 deg from the vertical).
    const glm::dvec3 skimming = *step10::refract_water_to_air(upward_at(critical - 1e-9), kUp);
    EXPECT_NEAR(skimming.y, 0, 1e-4);
}

TEST(Step10Optics, SnellsWindowHoldsTheSkyInA48Point6DegreeCone) {
    EXPECT_NEAR(step10::snells_window_angle(0), std::asin(1 / kWaterIndex), 1e-15);  // horizon
    EXPECT_NEAR(step10::snells_window_angle(0) / kDegree, 48.6, 0.05);
    EXPECT_NEAR(step10::snells_window_angle(ocean::kPi / 2), 0, 1e-15);  // zenith
    // And in between, the same angle the refracted sky ray makes with the vertical.
    for (double elevation : {10 * kDegree, 30 * kDegree, 60 * kDegree}) {
        const glm::dvec3 sky_ray{std::cos(elevation), -std::sin(elevation), 0};  // travelling down
        const glm::dvec3 in_water = *step10::refract_air_to_water(sky_ray, kUp);
        EXPECT_NEAR(step10::snells_window_angle(elevation), std::acos(-in_water.y), 1e-12);
        EXPECT_LT(step10::snells_window_angle(elevation), step10::critical_angle());
    }
}

TEST(Step10Optics, RefractionFollowsSnellAndRetracesItsPath) {
    // Random rays and tilted normals: the refracted ray is a unit vector in the plane of incidence,
    // n1 sin(in) = n2 sin(out), it bends towards the normal in water, and sending it back out
    // (water to air, reversed) gives the original ray back: light's paths are reversible.
    std::mt19937 random(10);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 normal = glm::normalize(glm::dvec3{0.3 * uniform(random), 1, 0.3 * uniform(random)});
        glm::dvec3 ray = glm::normalize(glm::dvec3{uniform(random), -1.5 - 0.5 * uniform(random), uniform(random)});
        const glm::dvec3 in_water = *step10::refract_air_to_water(ray, normal);
        const double sin_in = glm::length(glm::cross(ray, normal));
        const double sin_out = glm::length(glm::cross(in_water, normal));
        EXPECT_NEAR(glm::length(in_water), 1, 1e-12);
        EXPECT_NEAR(sin_in, kWaterIndex * sin_out, 1e-12);
        EXPECT_LT(sin_out, sin_in + 1e-15);
        EXPECT_NEAR(glm::dot(glm::cross(ray, normal), in_water), 0, 1e-12);  // same plane
        EXPECT_LT(glm::dot(in_water, normal), 0);                              // goes on down
        const glm::dvec3 back = *step10::refract_water_to_air(-in_water, normal);
        EXPECT_NEAR(glm::length(back + ray), 0, 1e-12);
    }
}

TEST(Step10Optics, ReflectanceIsTheSameSeenFromEitherSide) {
    // Stokes' relations: a ray and its reversed refracted ray see the same reflectance.
    for (double in_water = 0; in_water < step10::critical_angle(); in_water += 2 * kDegree) {
        const double in_air = std::asin(kWaterIndex * std::sin(in_water));
        EXPECT_NEAR(step10::reflectance_water_to_air(in_water),
                    step10::fresnel_reflectance(in_air, 1.0, kWaterIndex), 1e-12);
    }
    // At Brewster's angle, tan = n2 / n1, the p wave is not reflected: R is half the s reflectance
    // ((cos i - n cos t) / (cos i + n cos t))^2, with t = 90 deg - i there.
    const double brewster = std::atan(kWaterIndex);
    const double rs = (std::cos(brewster) - kWaterIndex * std::sin(brewster)) /
                      (std::cos(brewster) + kWaterIndex * std::sin(brewster));
    EXPECT_NEAR(step10::fresnel_reflectance(brewster, 1.0, kWaterIndex), 0.5 * rs * rs, 1e-12);
}

// The integral of f(cos theta) over the sphere, 2 pi times the integral over cos theta (Simpson).
double over_sphere(const std::function<double(double)>& f) {
    const int n = 200000;
    const double h = 2.0 / n;
    double sum = f(-1) + f(1);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(-1 + i * h);
    return ocean::kTwoPi * sum * h / 3;
}

TEST(Step10Water, TransmittanceOverTwiceThePathIsTheSquare) {
    for (const step10::WaterType& water : {step10::kPureSeaWater, step10::kClearOcean, step10::kCoastal}) {
        for (double path : {0.5, 3.0, 20.0}) {
            const glm::dvec3 once = step10::transmittance(water, path);
            const glm::dvec3 twice = step10::transmittance(water, 2 * path);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(twice[c], once[c] * once[c], 1e-15) << water.name;
        }
        EXPECT_EQ(step10::transmittance(water, 0), glm::dvec3(1));
    }
    // And 1 / c metres of water leaves exactly 1 / e.
    const glm::dvec3 c = step10::extinction(step10::kClearOcean);
    EXPECT_NEAR(step10::transmittance(step10::kClearOcean, 1 / c.g).g, std::exp(-1.0), 1e-15);
}

TEST(Step10Water, RedFadesFasterThanBlueInPureWater) {
    // Pope and Fry's table: a(612.5 nm) = 0.2665 /m against a(465 nm) = 0.01011 /m.
    const glm::dvec3 ten_metres = step10::transmittance(step10::kPureSeaWater, 10);
    EXPECT_LT(ten_metres.r, ten_metres.g);
    EXPECT_LT(ten_metres.g, ten_metres.b);
    EXPECT_LT(ten_metres.r, 0.1);  // 10 m of water takes nine tenths of the red
    EXPECT_GT(ten_metres.b, 0.8);  // and leaves most of the blue
    // Molecular scattering, smaller but bluer: lambda^-4.32 from 400 to 500 nm, 0.0029 /m at 500.
    EXPECT_NEAR(step10::pure_water_scattering(500) / step10::pure_water_scattering(400), std::pow(0.8, 4.32),
                1e-12);
    EXPECT_NEAR(step10::pure_water_scattering(500), 0.0029, 0.0001);
    const glm::dvec3 b = step10::pure_water_scattering();
    EXPECT_GT(b.b, b.r);
    // Coastal water's dissolved matter absorbs the blue: there green gets through best.
    const glm::dvec3 coastal = step10::transmittance(step10::kCoastal, 5);
    EXPECT_GT(coastal.g, coastal.b);
}

TEST(Step10Water, PhaseFunctionsIntegrateToOneOverTheSphere) {
    EXPECT_NEAR(over_sphere(step10::water_phase), 1, 1e-9);
    for (double g : {0.0, 0.5, 0.9}) {
        EXPECT_NEAR(over_sphere([g](double mu) { return step10::henyey_greenstein_phase(mu, g); }), 1, 1e-6);
        // Henyey-Greenstein's g is its mean cosine.
        EXPECT_NEAR(over_sphere([g](double mu) { return mu * step10::henyey_greenstein_phase(mu, g); }), g, 1e-6);
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(over_sphere([c](double mu) { return step10::phase(step10::kCoastal, mu)[c]; }), 1, 1e-6);
    // Morel's water: symmetric fore and aft, 1 + q at 0 deg over 1 at 90 deg.
    EXPECT_NEAR(step10::water_phase(1), step10::water_phase(-1), 1e-15);
    EXPECT_NEAR(step10::water_phase(1) / step10::water_phase(0), 1 + 3 * (16.06 / (4 * ocean::kPi) - 1), 1e-12);
}

TEST(Step10Water, SunlightAtDepthIsTheTransmittedBeamAttenuatedAlongItsSlantPath) {
    const glm::dvec3 sun{1, 1, 1};
    const double r0 = std::pow((kWaterIndex - 1) / (kWaterIndex + 1), 2);
    const glm::dvec3 overhead = step10::sunlight_at_depth(step10::kClearOcean, sun, ocean::kPi / 2, 7);
    const glm::dvec3 c = step10::extinction(step10::kClearOcean);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(overhead[i], (1 - r0) * std::exp(-c[i] * 7), 1e-12);
    // A low sun's beam runs longer through the water to reach the same depth: 7 m over the cosine
    // of its refracted angle, whose sine is cos(elevation) / n.
    const double elevation = 20 * kDegree;
    const glm::dvec3 low = step10::sunlight_at_depth(step10::kClearOcean, sun, elevation, 7);
    const double sin_refracted = std::cos(elevation) / kWaterIndex;
    const double slant = 7 / std::sqrt(1 - sin_refracted * sin_refracted);
    const double let_in = 1 - step10::fresnel_reflectance(ocean::kPi / 2 - elevation, 1.0, kWaterIndex);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(low[i], let_in * std::exp(-c[i] * slant), 1e-12);
    EXPECT_LT(low.b, overhead.b);
}

TEST(Step10Water, RadianceRelaxesToTheInScatterLimit) {
    // dL/ds = -c L + b p E, integrated metre by metre with small Runge-Kutta steps, must land on
    // the closed form L0 e^{-cL} + L_inf (1 - e^{-cL}), L_inf = b p E / c.
    const step10::WaterType& water = step10::kCoastal;
    const glm::dvec3 sun = step10::sunlight_at_depth(water, {1, 1, 1}, 60 * kDegree, 3);
    const double cos_theta = 0.7;
    const glm::dvec3 source = step10::scattering(water) * step10::phase(water, cos_theta) * sun;
    const glm::dvec3 c = step10::extinction(water);
    const glm::dvec3 limit = step10::in_scatter_limit(water, cos_theta, sun);
    const glm::dvec3 surface{0.8, 0.5, 0.3};
    glm::dvec3 radiance = surface;
    const double step = 1e-3;
    auto slope = [&](const glm::dvec3& l) { return -c * l + source; };
    for (int i = 1; i <= 10000; ++i) {
        const glm::dvec3 k1 = slope(radiance), k2 = slope(radiance + 0.5 * step * k1);
        const glm::dvec3 k3 = slope(radiance + 0.5 * step * k2), k4 = slope(radiance + step * k3);
        radiance += step / 6 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if (i % 1000 == 0) {
            const glm::dvec3 expected = step10::seen_through_water(water, surface, i * step, limit);
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(radiance[ch], expected[ch], 1e-12) << i * step << " m";
        }
    }
    // Far enough, the surface is gone and only the water's own glow is left.
    const glm::dvec3 far = step10::seen_through_water(water, surface, 1000, limit);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(far[ch], limit[ch], 1e-12);
}

TEST(Step10Caustics, FlatSeaLightsTheFloorEvenly) {
    for (double zenith : {0.0, 30 * kDegree}) {
        step10::CausticSea sea;
        sea.amplitude = 0;
        sea.sun_zenith = zenith;
        sea.rays = 20000;
        const double expected = 1 - step10::fresnel_reflectance(zenith, 1.0, kWaterIndex);
        for (double e : step10::seabed_irradiance(sea).irradiance) EXPECT_NEAR(e, expected, 1e-9);
    }
}

TEST(Step10Caustics, TheFloorReceivesAllTheTransmittedLight) {
    // Rays are neither made nor lost between the surface and the floor: the mean irradiance is
    // the transmitted fraction, within 2 % of a flat sea's 1 - R (the slopes are small), and
    // exactly the Fresnel transmittance averaged over the surface (computed here, not traced).
    for (double zenith : {0.0, 30 * kDegree}) {
        step10::CausticSea sea;
        sea.sun_zenith = zenith;
        for (double depth : {1.0, 8.0, 30.0}) {
            sea.depth = depth;
            const double mean = step10::seabed_irradiance(sea).mean();
            const double flat = 1 - step10::fresnel_reflectance(zenith, 1.0, kWaterIndex);
            EXPECT_NEAR(mean / flat, 1, 0.02) << depth << " m";
            const glm::dvec3 ray{std::sin(zenith), -std::cos(zenith), 0};
            const int n = 100000;
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                const double x = (i + 0.5) / n * ocean::kTwoPi / sea.wavenumber;
                const double slope = -sea.amplitude * sea.wavenumber * std::sin(sea.wavenumber * x);
                const glm::dvec3 scaled_normal{-slope, 1, 0};
                const double incidence = std::acos(-glm::dot(ray, glm::normalize(scaled_normal)));
                sum += (1 - step10::fresnel_reflectance(incidence, 1.0, kWaterIndex)) *
                       std::abs(glm::dot(ray, scaled_normal)) / std::cos(zenith);
            }
            EXPECT_NEAR(mean, sum / n, 1e-6) << depth << " m";
        }
    }
}

// The floor at each depth, sun overhead. Bins of 2 mm: a caustic's binned peak sits just past
// where the rays cross, by about the depth over which the two fold lines leaving the cusp stay
// within one bin (200 bins put it 10 % past the focus, 1000 bins 3 %, 4000 bins on it).
std::vector<step10::SeabedIrradiance> floors_at(const std::vector<double>& depths) {
    std::vector<step10::SeabedIrradiance> floors;
    step10::CausticSea sea;
    sea.bins = 1000;
    sea.rays = 400000;
    for (double depth : depths) {
        sea.depth = depth;
        floors.push_back(step10::seabed_irradiance(sea));
    }
    return floors;
}

TEST(Step10Caustics, BrightestWhereTheCrestFocuses) {
    // The crests are lenses of focal depth n / ((n - 1) a k^2): 8.1 m for a = 5 cm, 2 m waves.
    const step10::CausticSea sea;
    const double focus = step10::crest_focal_depth(sea);
    EXPECT_NEAR(focus, kWaterIndex / ((kWaterIndex - 1) * sea.amplitude * sea.wavenumber * sea.wavenumber), 1e-12);
    EXPECT_NEAR(focus, 8.11, 0.005);
    std::vector<double> depths;
    for (double d = 0.5 * focus; d < 1.5 * focus; d += 0.025 * focus) depths.push_back(d);
    const std::vector<step10::SeabedIrradiance> floors = floors_at(depths);
    std::size_t brightest = 0;
    for (std::size_t i = 0; i < floors.size(); ++i)
        if (floors[i].peak() > floors[brightest].peak()) brightest = i;
    EXPECT_NEAR(depths[brightest] / focus, 1, 0.1) << "brightest at " << depths[brightest] << " m";
    EXPECT_GT(floors[brightest].peak_over_mean(), 20);  // a real caustic, not a ripple
}

TEST(Step10Caustics, TheCausticLiesUnderTheCrestOrDownSun) {
    // The crests converge the light (the troughs spread it): at the focal depth the brightest
    // bin is under a crest (x = 0). With the sun 20 degrees from the zenith, the light goes on
    // in the water 14.9 degrees from the vertical (sin 20 / n), so the bright line shifts by
    // depth tan(14.9 deg) downsun, here 1.1 m at 4 m (the focus moves too, so only to 5 cm).
    step10::CausticSea sea;
    sea.depth = step10::crest_focal_depth(sea);
    const double wavelength = ocean::kTwoPi / sea.wavenumber;
    auto brightest_x = [&](const step10::CausticSea& s) {
        const step10::SeabedIrradiance floor = step10::seabed_irradiance(s);
        const auto peak = std::max_element(floor.irradiance.begin(), floor.irradiance.end());
        return (double(peak - floor.irradiance.begin()) + 0.5) * wavelength / s.bins;
    };
    EXPECT_NEAR(std::remainder(brightest_x(sea), wavelength), 0, 2 * wavelength / sea.bins);
    sea.sun_zenith = 20 * kDegree;
    sea.depth = 4;
    const double shift = (sea.depth + sea.amplitude) * std::tan(std::asin(std::sin(sea.sun_zenith) / kWaterIndex));
    EXPECT_NEAR(std::remainder(brightest_x(sea) - shift, wavelength), 0, 0.05);
}

TEST(Step10Caustics, ASlantedSunFocusesWhereCoddingtonSays) {
    // Exercise 3's answer against the ray tracing: with the sun 20, 35 and 50 degrees from the
    // vertical, the floor is brightest at the slanted focal depth within 10 % (searched in steps
    // of 5 %; measured: on it at all three), and that depth differs from the overhead sun's.
    step10::CausticSea sea;
    sea.bins = 1000;
    sea.rays = 400000;
    const double overhead = step10::crest_focal_depth(sea);
    EXPECT_NEAR(step10::slanted_crest_focal_depth(sea.amplitude, sea.wavenumber, 0), overhead, 1e-12 * overhead);
    for (double zenith : {20 * kDegree, 35 * kDegree, 50 * kDegree}) {
        sea.sun_zenith = zenith;
        const double focus = step10::slanted_crest_focal_depth(sea.amplitude, sea.wavenumber, zenith);
        EXPECT_GT(std::abs(focus - overhead), 0.1 * overhead);
        double brightest_depth = 0, brightest = 0;
        for (double d = 0.7 * focus; d < 1.31 * focus; d += 0.05 * focus) {
            sea.depth = d;
            const double peak = step10::seabed_irradiance(sea).peak();
            if (peak > brightest) brightest = peak, brightest_depth = d;
        }
        std::printf("sun %2.0f deg from the vertical: focus %.2f m, brightest at %.2f m\n", zenith / kDegree, focus,
                    brightest_depth);
        EXPECT_NEAR(brightest_depth / focus, 1, 0.1) << zenith / kDegree << " deg";
    }
}

TEST(Step10Caustics, ContrastFallsPastTheFocus) {
    // Past the focus the rays from each crest spread again and overlap their neighbours': the
    // floor evens out. (The peak alone does not fall steadily: folds from neighbouring crests
    // cross now and then, which is why contrast is measured as std / mean over the whole floor.)
    const double focus = step10::crest_focal_depth(step10::CausticSea{});
    const std::vector<double> depths{1.05 * focus, 1.25 * focus, 1.5 * focus, 2 * focus, 3 * focus, 4 * focus};
    const std::vector<step10::SeabedIrradiance> floors = floors_at(depths);
    for (std::size_t i = 1; i < floors.size(); ++i) {
        EXPECT_LT(floors[i].contrast(), floors[i - 1].contrast()) << depths[i] << " m";
        EXPECT_LT(floors[i].peak_over_mean(), floors[0].peak_over_mean()) << depths[i] << " m";
    }
    // And shallower than the focus the pattern is still forming: gentler than at it.
    const std::vector<step10::SeabedIrradiance> shallow = floors_at({0.3 * focus});
    EXPECT_LT(shallow[0].contrast(), 0.2 * floors[0].contrast());
}

}  // namespace
