#include "step06_foam_sky/patch_grid.hpp"

#include <glm/geometric.hpp>

namespace step06 {

std::vector<glm::vec4> frustum_planes(const glm::mat4& m) {
    auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    std::vector<glm::vec4> planes{row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                  row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

}  // namespace step06
