#include "step10_underwater/water_colour.hpp"

#include "common/constants.hpp"
#include "step10_underwater/optics.hpp"

#include <cmath>

namespace step10 {

namespace {
// Morel's scattering of pure sea water at 90 degrees at 400 nm (1/m/sr), and the factor from it
// to the total over the sphere (Riops' R/spectral.bw.R, after Mobley 1994).
constexpr double kBeta90At400 = 4.72e-4;
constexpr double kTotalOverBeta90 = 16.06;
constexpr double kWavelengthExponent = 4.32;

glm::dvec3 per_channel(double (*f)(double)) {
    return {f(kChannelWavelength.r), f(kChannelWavelength.g), f(kChannelWavelength.b)};
}

glm::dvec3 exp_of(const glm::dvec3& v) { return {std::exp(v.r), std::exp(v.g), std::exp(v.b)}; }
}  // namespace

double pure_water_scattering(double wavelength) {
    return kTotalOverBeta90 * kBeta90At400 * std::pow(400.0 / wavelength, kWavelengthExponent);
}

glm::dvec3 pure_water_scattering() { return per_channel(pure_water_scattering); }

double water_phase(double cos_theta) {
    const double q = 3 * (kTotalOverBeta90 / (4 * ocean::kPi) - 1);
    return (1 + q * cos_theta * cos_theta) / (4 * ocean::kPi * (1 + q / 3));
}

double henyey_greenstein_phase(double cos_theta, double g) {
    const double denominator = 1 + g * g - 2 * g * cos_theta;
    return (1 - g * g) / (4 * ocean::kPi * denominator * std::sqrt(denominator));
}

glm::dvec3 absorption(const WaterType& water) { return kPureWaterAbsorption + water.added_absorption; }

glm::dvec3 scattering(const WaterType& water) { return pure_water_scattering() + water.particle_scattering; }

glm::dvec3 extinction(const WaterType& water) { return absorption(water) + scattering(water); }

glm::dvec3 transmittance(const WaterType& water, double path_length) {
    return exp_of(-extinction(water) * path_length);
}

glm::dvec3 phase(const WaterType& water, double cos_theta) {
    const glm::dvec3 b_water = pure_water_scattering();
    const glm::dvec3 b_particles = water.particle_scattering;
    return (b_water * water_phase(cos_theta) +
            b_particles * henyey_greenstein_phase(cos_theta, water.particle_g)) /
           (b_water + b_particles);
}

glm::dvec3 sunlight_at_depth(const WaterType& water, const glm::dvec3& sun, double elevation, double depth) {
    const double incidence = ocean::kPi / 2 - elevation;  // from the vertical, in air
    const double transmitted = 1 - fresnel_reflectance(incidence, 1.0, kWaterIndex);
    const double refracted = snells_window_angle(elevation);  // the same Snell, seen from the sun's side
    return sun * transmitted * transmittance(water, depth / std::cos(refracted));
}

glm::dvec3 in_scatter_limit(const WaterType& water, double cos_theta, const glm::dvec3& sun_at_depth) {
    return scattering(water) * phase(water, cos_theta) * sun_at_depth / extinction(water);
}

glm::dvec3 seen_through_water(const WaterType& water, const glm::dvec3& surface, double path_length,
                              const glm::dvec3& limit) {
    const glm::dvec3 t = transmittance(water, path_length);
    return surface * t + limit * (1.0 - t);
}

const WaterType* water_type_named(const std::string& name) {
    for (const WaterType& w : kWaterTypes)
        if (name == w.name) return &w;
    return nullptr;
}

}  // namespace step10
