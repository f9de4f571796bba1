// The answers of the `queries` parameter drawn as dots where the water is (query_points.vert and
// .frag): what a game's particles or floating debris would ask of the sea, made visible.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace step07 {

class QueryDots {
public:
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // `dots` in world metres (double), drawn from `origin` (the sea's world origin near the
    // camera) with the frame's view-projection, depth-tested against the sea.
    void draw(const std::vector<glm::dvec3>& dots, glm::dvec3 origin, const glm::mat4& view_projection);

private:
    ocean::ProgramFactory programs_;
    ocean::Buffer buffer_;
    ocean::VertexArray vao_;
};

}  // namespace step07
