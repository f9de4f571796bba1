// The texel of the camera-centred level that holds a point, if the cascades were combined around
// the camera (Crest's design): the CPU reference for shaders/combined_levels.glsl, which says why.
// The levels are square, nested, each twice the extent of the one inside it, each `texels` on a
// side; the innermost's texel is the finest cascade's. Used to measure what such levels would
// cost the picture (the `combined_texels` setting, README), not to draw.
#pragma once

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace step06 {

inline double combined_level_texel(glm::dvec2 offset_from_centre, double texels, double finest_texel) {
    const double reach = std::max(std::abs(offset_from_centre.x), std::abs(offset_from_centre.y));
    const double level = std::ceil(std::log2(std::max(2 * reach / (texels * finest_texel), 1.0)));
    return finest_texel * std::exp2(level);
}

}  // namespace step06
