// Chapter 9's unit source and its image (the primer's G), on their own so that the exercises
// (./ocean exercise step09_radiation 1 and 2) can empty them: source_hull.cpp sums G over the hull's
// panels.
#pragma once

#include <glm/vec3.hpp>

namespace step09 {

// The image's strength against its source's: -1, a sink, keeps phi = 0 on the surface (the primer:
// at the instant of a sudden motion the surface stays at the air's pressure). +1 would be a rigid
// lid: a surface that cannot rise.
constexpr double kImageStrength = -1;

// What a unit source (1 m^3/s of water out of it) at xi under the surface y = 0, with its image at xi
// mirrored in the surface (strength kImageStrength), does at a point x of the water: the potential
// there, G = (1/4 pi) (-1/|x - xi| - kImageStrength/|x - xi'|), and the flow along the unit vector n,
// n . grad G (m/s per m^3/s).
struct SourceAt {
    double potential = 0, along = 0;
};
SourceAt source_with_image(glm::dvec3 x, glm::dvec3 xi, glm::dvec3 n);

// The water the same source and its image put up through the surface y = 0 (m/s per m^3/s, up
// positive), `across` metres from the point above the source, which is `depth` metres down.
double flow_through_surface(double across, double depth);

}  // namespace step09
