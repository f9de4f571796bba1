#include "common/frustum.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ocean {

std::vector<glm::vec4> frustum_planes(const glm::mat4& m) {
    auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    std::vector<glm::vec4> planes{row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                  row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

bool box_outside_frustum(const std::vector<glm::vec4>& planes, glm::vec3 lo, glm::vec3 hi) {
    for (const glm::vec4& plane : planes) {
        // The box's corner furthest along the plane's inward normal: if even it is outside, all are.
        const glm::vec3 farthest = glm::mix(lo, hi, glm::greaterThan(glm::vec3(plane), glm::vec3(0.0f)));
        if (glm::dot(glm::vec3(plane), farthest) + plane.w < 0.0f) return true;
    }
    return false;
}

}  // namespace ocean
