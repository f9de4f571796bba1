#include "step09_radiation/image_source.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step09 {

SourceAt source_with_image(glm::dvec3 x, glm::dvec3 xi, glm::dvec3 n) {
    SourceAt at;
    for (int mirrored = 0; mirrored < 2; ++mirrored) {
        // A source of strength q at s: the primer's point source, its potential and its outward flow.
        const glm::dvec3 s = mirrored ? glm::dvec3(xi.x, -xi.y, xi.z) : xi;
        const double q = mirrored ? kImageStrength : 1.0;
        const glm::dvec3 d = x - s;
        const double r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        at.potential += -q / (4 * ocean::kPi * r);
        at.along += q * (d.x * n.x + d.y * n.y + d.z * n.z) / (4 * ocean::kPi * r * r * r);
    }
    return at;
}

double flow_through_surface(double across, double depth) {
    // Both are depth metres from the surface, so the same r away: the source pushes the water up
    // through it, an image sink above draws it up as much; a rigid lid's image (+1) cancels it.
    const double r = std::sqrt(across * across + depth * depth);
    return (1 - kImageStrength) * depth / (4 * ocean::kPi * r * r * r);
}

}  // namespace step09
