#include "common/grid.hpp"

namespace ocean {

std::vector<glm::vec2> grid_positions(glm::vec2 size, int x_quads, int z_quads) {
    std::vector<glm::vec2> positions;
    positions.reserve(std::size_t(x_quads + 1) * std::size_t(z_quads + 1));
    for (int j = 0; j <= z_quads; ++j)
        for (int i = 0; i <= x_quads; ++i)
            positions.emplace_back(size.x * (float(i) / float(x_quads) - 0.5f),
                                   size.y * (float(j) / float(z_quads) - 0.5f));
    return positions;
}

std::vector<unsigned> grid_triangle_indices(int x_quads, int z_quads) {
    std::vector<unsigned> indices;
    indices.reserve(std::size_t(x_quads) * std::size_t(z_quads) * 6);
    const unsigned row = unsigned(x_quads + 1);
    for (unsigned j = 0; j < unsigned(z_quads); ++j)
        for (unsigned i = 0; i < unsigned(x_quads); ++i) {
            const unsigned a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            // z grows towards the viewer, so (a, c, b) turns counter-clockwise seen from above.
            indices.insert(indices.end(), {a, c, b, b, c, d});
        }
    return indices;
}

void GridMesh::build(glm::vec2 size, int x_quads, int z_quads) {
    const auto positions = grid_positions(size, x_quads, z_quads);
    const auto indices = grid_triangle_indices(x_quads, z_quads);
    vertices_ = make_buffer();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(positions.size() * sizeof(glm::vec2)),
                         positions.data(), 0);
    indices_ = make_buffer();
    glNamedBufferStorage(indices_.id(), GLsizeiptr(indices.size() * sizeof(unsigned)), indices.data(), 0);
    vao_ = make_vertex_array();
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(glm::vec2));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
    vertex_count_ = int(positions.size());
    index_count_ = GLsizei(indices.size());
}

void GridMesh::draw(bool wireframe) const {
    glBindVertexArray(vao_.id());
    if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

}  // namespace ocean
