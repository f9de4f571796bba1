// Chapter 7.7's Archimedes, cell by cell, as pure functions (no state, no GL): what a hull's cells
// feel from the water around them. floating_body.cpp adds the drag and integrates; exercise 2
// (./ocean exercise step07_buoyancy 2) empties buoyancy() in a copy of hull_forces.cpp.
#pragma once

#include "common/constants.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace step07 {

constexpr double kWaterDensity = 1025;  // kg/m^3, sea water

// One piece of the hull: centre and sides in the body's frame, and its volume (a sphere's cubes
// are scaled so that they add up to the sphere's volume).
struct HullCell {
    glm::dvec3 offset{0.0}, size{0.0};
    double volume = 0;
};

// A cell's vertical half-extent, tilted with the body: its three sides projected on y.
double vertical_half_extent(const glm::dmat3& rotation, const HullCell& cell);
// The share of a cell of that half-extent, centred at height centre_y, below the water line:
// its vertical extent under the water, 0 (dry) to 1 (under).
double wet_share(double water_line, double centre_y, double half_extent);

// A force and its torque about the centre of mass.
struct Wrench {
    glm::dvec3 force{0.0}, torque{0.0};
};

// Archimedes over the hull: each cell i (centred at centre_of_mass + rotation * offset, the water's
// height above its centre water_lines[i]) is pushed up by the weight of the water it displaces,
// rho_w g V wet_share, at the middle of its submerged part (on its vertical through the centre,
// half the wet height above the cell's bottom: a vertical force's torque does not depend on the
// height it acts at, so it is the torque of a force at the cell's centre); summed, with the
// torques about the centre of mass.
Wrench buoyancy(const std::vector<HullCell>& cells, const glm::dmat3& rotation, glm::dvec3 centre_of_mass,
                const std::vector<double>& water_lines);

// A sphere needs no cells: the water it displaces is the spherical cap under the water line,
// exactly. With the water line `draft` above the sphere's lowest point, the cap holds
//     V = pi d^2 (3 r - d) / 3,   d = draft clamped to [0, 2 r]
// (0 dry, 4/3 pi r^3 under; the disc slices pi (2 r z - z^2) integrated from 0 to d).
double spherical_cap_volume(double radius, double draft);
// Archimedes on a sphere whose centre is at height centre_y, the water at water_line (the sea's
// height under its centre: a buoy is small against the waves that lift it): rho_w g V up, through
// the centre. The pressure pushes along the sphere's normals, which all pass through its centre,
// so a uniform sphere feels no buoyant torque about it, whatever its orientation.
glm::dvec3 sphere_buoyancy(double radius, double centre_y, double water_line);
// The period, in seconds, of a floating sphere's small heave about its rest at `draft` (0 < draft <
// 2 radius), with step07's linear drag (per kilogram of water displaced, 1/s) and no added mass:
// Archimedes linearised about the rest, as motion.md's section 10 does for a box. Infinite where the drag
// leaves no oscillation. Exercise 3 (./ocean exercise step07_buoyancy 3) empties it;
// tests/test_floating_body.cpp holds the program's buoy, raised and let go, to it.
double sphere_heave_period(double radius, double draft, double linear_drag);

}  // namespace step07
