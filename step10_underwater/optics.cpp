#include "step10_underwater/optics.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace step10 {

std::optional<glm::dvec3> refract(const glm::dvec3& direction, const glm::dvec3& normal, double n_from,
                                  double n_to) {
    // Face the normal against the ray, so cos_in is the cosine of the angle of incidence (>= 0).
    const glm::dvec3 facing = glm::dot(direction, normal) > 0 ? -normal : normal;
    const double cos_in = -glm::dot(direction, facing);
    const double ratio = n_from / n_to;
    // Snell: n_from sin(in) = n_to sin(out); the tangential part of the direction scales by the ratio.
    const double sin2_out = ratio * ratio * (1 - cos_in * cos_in);
    if (sin2_out > 1) return std::nullopt;
    const double cos_out = std::sqrt(1 - sin2_out);
    return ratio * direction + (ratio * cos_in - cos_out) * facing;
}

std::optional<glm::dvec3> refract_water_to_air(const glm::dvec3& direction, const glm::dvec3& normal) {
    return refract(direction, normal, kWaterIndex, 1.0);
}

std::optional<glm::dvec3> refract_air_to_water(const glm::dvec3& direction, const glm::dvec3& normal) {
    return refract(direction, normal, 1.0, kWaterIndex);
}

double fresnel_reflectance(double incidence, double n_from, double n_to) {
    const double sin_out = n_from / n_to * std::sin(incidence);
    if (sin_out >= 1) return 1;  // at and past the critical angle nothing is transmitted
    const double cos_in = std::cos(incidence);
    const double cos_out = std::sqrt(1 - sin_out * sin_out);
    // The amplitude ratios for the field across (s) and along (p) the plane of incidence.
    const double rs = (n_from * cos_in - n_to * cos_out) / (n_from * cos_in + n_to * cos_out);
    const double rp = (n_from * cos_out - n_to * cos_in) / (n_from * cos_out + n_to * cos_in);
    return std::clamp(0.5 * (rs * rs + rp * rp), 0.0, 1.0);
}

double reflectance_water_to_air(double incidence_in_water) {
    return fresnel_reflectance(incidence_in_water, kWaterIndex, 1.0);
}

double transmittance_water_to_air(double incidence_in_water) {
    return 1 - reflectance_water_to_air(incidence_in_water);
}

double critical_angle() { return std::asin(1 / kWaterIndex); }

double snells_window_angle(double elevation) {
    // The sky ray meets the flat surface at 90 deg - elevation from the vertical (its sine is
    // cos(elevation)) and bends towards the normal by Snell's law.
    return std::asin(std::cos(elevation) / kWaterIndex);
}

}  // namespace step10
