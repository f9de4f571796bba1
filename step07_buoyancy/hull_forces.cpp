#include "step07_buoyancy/hull_forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace step07 {

double vertical_half_extent(const glm::dmat3& rotation, const HullCell& cell) {
    return 0.5 * (std::abs(rotation[0].y) * cell.size.x + std::abs(rotation[1].y) * cell.size.y +
                  std::abs(rotation[2].y) * cell.size.z);
}

double wet_share(double water_line, double centre_y, double half_extent) {
    return std::clamp((water_line - (centre_y - half_extent)) / (2 * half_extent), 0.0, 1.0);
}

Wrench buoyancy(const std::vector<HullCell>& cells, const glm::dmat3& rotation, glm::dvec3 centre_of_mass,
                const std::vector<double>& water_lines) {
    Wrench total;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const glm::dvec3 arm = rotation * cells[i].offset;
        const double half = vertical_half_extent(rotation, cells[i]);
        const double wet = wet_share(water_lines[i], centre_of_mass.y + arm.y, half);
        const glm::dvec3 force(0.0, kWaterDensity * ocean::kGravity * wet * cells[i].volume, 0.0);
        // The submerged part runs from the cell's bottom (arm.y - half) up wet * 2 half: its middle.
        const glm::dvec3 at = arm + glm::dvec3(0.0, -half + wet * half, 0.0);
        total.force += force;
        total.torque += glm::cross(at, force);
    }
    return total;
}

double spherical_cap_volume(double radius, double draft) {
    const double d = std::clamp(draft, 0.0, 2 * radius);
    return ocean::kPi * d * d * (3 * radius - d) / 3;
}

glm::dvec3 sphere_buoyancy(double radius, double centre_y, double water_line) {
    const double volume = spherical_cap_volume(radius, water_line - (centre_y - radius));
    return {0.0, kWaterDensity * ocean::kGravity * volume, 0.0};
}

double sphere_heave_period(double radius, double draft, double linear_drag) {
    // Raised y above its rest, the cap gains the waterplane's disc times y: the spring rho_w g S
    // against the mass rho_w V(draft) that the rest displaces, S = dV/d(draft).
    const double waterplane = ocean::kPi * draft * (2 * radius - draft);
    const double omega_squared = ocean::kGravity * waterplane / spherical_cap_volume(radius, draft) -
                                 0.25 * linear_drag * linear_drag;
    if (omega_squared <= 0) return std::numeric_limits<double>::infinity();
    return 2 * ocean::kPi / std::sqrt(omega_squared);
}

}  // namespace step07
