// Chapter 5.1 on the CPU: how finely to cut each patch of the sea. Near the camera a patch edge
// is cut into many segments, far away into few: level = tess_scale * patch_size / distance,
// clamped to [1, 64], the same formula as ocean.tesc (tested against its primitive count).
#pragma once

#include <algorithm>
#include <cmath>

namespace step06 {

constexpr double kMaxTessLevel = 64;

inline double tessellation_level(double distance, double patch_size, double tess_scale) {
    return std::clamp(tess_scale * patch_size / std::max(distance, 1e-3), 1.0, kMaxTessLevel);
}

// With equal spacing the hardware rounds a level up to an integer; a quad patch whose outer and
// inner levels are all L becomes 2 L^2 triangles.
inline long triangles_for_uniform_level(double level) {
    const long l = long(std::ceil(level));
    return 2 * l * l;
}

}  // namespace step06
