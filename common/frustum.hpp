// The view frustum, for culling: its six planes from a view-projection matrix (Gribb and
// Hartmann) and a box test. step05 culls its grid's chunks on the CPU with it; step06 hands the
// planes to ocean.tesc, which makes the same test per patch on the GPU.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace ocean {

// (normal, d) with normals pointing inwards and normalised: dot(normal, p) + d >= 0 inside.
std::vector<glm::vec4> frustum_planes(const glm::mat4& view_projection);

// True when the axis-aligned box [lo, hi] lies wholly outside one of the planes (so nothing in
// it can be seen). A box that straddles a corner of the frustum may pass though unseen: culling
// only has to be safe, not exact.
bool box_outside_frustum(const std::vector<glm::vec4>& planes, glm::vec3 lo, glm::vec3 hi);

}  // namespace ocean
