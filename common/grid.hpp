// The water plane: (x_quads+1)(z_quads+1) vertices on a flat grid centred on the origin, each
// holding only its rest position (x, z); the vertex shader lifts it into a wave.
#pragma once

#include "common/gl.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace ocean {

// Rest positions, row by row along x; size in metres, counts in quads.
std::vector<glm::vec2> grid_positions(glm::vec2 size, int x_quads, int z_quads);
// Two counter-clockwise (seen from +y) triangles a quad.
std::vector<unsigned> grid_triangle_indices(int x_quads, int z_quads);

class GridMesh {
public:
    void build(glm::vec2 size, int x_quads, int z_quads);
    // GL_TRIANGLES (attribute 0 is vec2 (x, z)), or only their edges when `wireframe`.
    void draw(bool wireframe = false) const;
    int vertex_count() const { return vertex_count_; }
    GLuint vertex_buffer() const { return vertices_.id(); }
    GLuint vertex_array() const { return vao_.id(); }

private:
    VertexArray vao_;
    Buffer vertices_, indices_;
    int vertex_count_ = 0;
    GLsizei index_count_ = 0;
};

}  // namespace ocean
