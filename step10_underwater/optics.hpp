// Chapter 10, the surface seen from below: what happens to light where water meets air.
// Everything here is geometry and the Fresnel equations for a flat interface between water
// (index kWaterIndex) and air (index 1), in double precision: the reference the shaders are held to.
#pragma once

#include <glm/vec3.hpp>

#include <optional>

namespace step10 {

// Pure water's index for visible light at room temperature (about 1.333 across 450..650 nm);
// the chapter ignores its small change with wavelength, so the colours refract alike.
constexpr double kWaterIndex = 1.333;

// Snell's law in vector form for a ray crossing from index n_from into n_to. `direction` is the
// unit direction of travel and `normal` a unit normal of the surface, either way up: it is turned
// to face the incoming ray. Empty when sin of the refracted angle would exceed 1: total internal
// reflection, which only happens going from the denser side (water) into the lighter (air).
std::optional<glm::dvec3> refract(const glm::dvec3& direction, const glm::dvec3& normal, double n_from,
                                  double n_to);
std::optional<glm::dvec3> refract_water_to_air(const glm::dvec3& direction, const glm::dvec3& normal);
std::optional<glm::dvec3> refract_air_to_water(const glm::dvec3& direction, const glm::dvec3& normal);

// The unpolarized Fresnel reflectance for light meeting the interface at `incidence` radians from
// the normal on the side of index n_from: the mean of the s and p reflectances, exact (no Schlick).
// 1 past the critical angle. The same formula both ways: swapping the sides and the angles gives
// the same R (Stokes' relations), which is why one function serves the sea seen from above and below.
double fresnel_reflectance(double incidence, double n_from, double n_to);

// From water into air, the angle of incidence measured in the water: how much of the light coming
// up from below the surface bounces back down (R) and how much leaves into the sky (1 - R).
double reflectance_water_to_air(double incidence_in_water);
double transmittance_water_to_air(double incidence_in_water);

// asin(1 / n), 48.6 degrees for water: past it, light from below cannot leave.
double critical_angle();

// Snell's window: a diver looking up sees the whole sky squeezed into a cone. A sky ray at
// `elevation` radians above the horizon arrives under a flat surface at this many radians from
// the vertical: asin(cos(elevation) / n). The horizon maps to the critical angle, the zenith to 0.
double snells_window_angle(double elevation);

}  // namespace step10
