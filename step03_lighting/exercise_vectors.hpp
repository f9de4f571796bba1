// The exercise framework hands its checks' references GLM vectors (exercises/exercise.hpp); this
// chapter's CPU reference, and whatever is built on it, take their own Vec3 (normals.hpp).
#pragma once

#include <glm/vec3.hpp>

#include "step03_lighting/normals.hpp"

namespace step03 {

inline Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace step03
