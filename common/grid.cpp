#include "common/grid.hpp"

#include "common/camera.hpp"
#include "common/frustum.hpp"
#include "common/gpu_timer.hpp"
#include "common/shader.hpp"

#include <algorithm>

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

GridTriangles grid_triangles(glm::vec2 size, int x_quads, int z_quads) {
    GridTriangles t;
    t.indices.reserve(std::size_t(x_quads) * std::size_t(z_quads) * 6);
    const unsigned row = unsigned(x_quads + 1);
    const glm::vec2 quad = size / glm::vec2(float(x_quads), float(z_quads)), origin = -0.5f * size;
    for (int cz = 0; cz < z_quads; cz += kChunkQuads)
        for (int cx = 0; cx < x_quads; cx += kChunkQuads) {
            GridChunk chunk;
            chunk.first = t.indices.size();
            const int x_end = std::min(cx + kChunkQuads, x_quads), z_end = std::min(cz + kChunkQuads, z_quads);
            for (unsigned j = unsigned(cz); j < unsigned(z_end); ++j)
                for (unsigned i = unsigned(cx); i < unsigned(x_end); ++i) {
                    const unsigned a = j * row + i, b = a + 1, c = a + row, d = c + 1;
                    // z grows towards the viewer, so (a, c, b) turns counter-clockwise seen from above.
                    t.indices.insert(t.indices.end(), {a, c, b, b, c, d});
                }
            chunk.count = t.indices.size() - chunk.first;
            chunk.lo = origin + quad * glm::vec2(float(cx), float(cz));
            chunk.hi = origin + quad * glm::vec2(float(x_end), float(z_end));
            t.chunks.push_back(chunk);
        }
    return t;
}

std::vector<std::size_t> visible_chunks(const std::vector<GridChunk>& chunks, const glm::mat4& view_projection,
                                        float margin) {
    const std::vector<glm::vec4> planes = frustum_planes(view_projection);
    std::vector<std::size_t> visible;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        const glm::vec3 lo(chunks[c].lo.x - margin, -margin, chunks[c].lo.y - margin);
        const glm::vec3 hi(chunks[c].hi.x + margin, margin, chunks[c].hi.y + margin);
        if (!box_outside_frustum(planes, lo, hi)) visible.push_back(c);
    }
    return visible;
}

std::vector<unsigned> triangle_edges(const std::vector<unsigned>& triangles) {
    std::vector<unsigned> edges;
    edges.reserve(2 * triangles.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const unsigned a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        edges.insert(edges.end(), {a, b, b, c, c, a});
    }
    return edges;
}

void GridMesh::build(glm::vec2 size, int x_quads, int z_quads) {
    const auto positions = grid_positions(size, x_quads, z_quads);
    GridTriangles triangles = grid_triangles(size, x_quads, z_quads);
    const std::vector<unsigned>& indices = triangles.indices;
    vertices_ = make_buffer();
    buffer_data(vertices_, GLsizeiptr(positions.size() * sizeof(glm::vec2)), positions.data(), GL_STATIC_DRAW);
    // An index buffer is attached to its vertex array before it is filled: WebGL gives a buffer its
    // kind (indices or other data) at its first binding, and refuses to change it afterwards.
    vao_ = make_vertex_array();
    vertex_attribute(vao_, 0, vertices_, 2, sizeof(glm::vec2));  // attribute 0: the rest position (x, z)
    indices_ = make_buffer();
    element_buffer(vao_, indices_);
    buffer_data(indices_, GLsizeiptr(indices.size() * sizeof(unsigned)), indices.data(), GL_STATIC_DRAW);
#if defined(OCEAN_GL_ES)
    const std::vector<unsigned> edges = triangle_edges(indices);
    edges_vao_ = make_vertex_array();
    vertex_attribute(edges_vao_, 0, vertices_, 2, sizeof(glm::vec2));
    edges_ = make_buffer();
    element_buffer(edges_vao_, edges_);
    buffer_data(edges_, GLsizeiptr(edges.size() * sizeof(unsigned)), edges.data(), GL_STATIC_DRAW);
#endif
    vertex_count_ = int(positions.size());
    index_count_ = GLsizei(indices.size());
    chunks_ = std::move(triangles.chunks);
}

void GridMesh::draw(bool wireframe) const { draw_ranges({0}, {std::size_t(index_count_)}, wireframe); }

std::size_t GridMesh::draw_visible(const glm::mat4& view_projection, float margin, bool wireframe) const {
    const std::vector<std::size_t> visible = visible_chunks(chunks_, view_projection, margin);
    std::vector<std::size_t> firsts, counts;
    for (std::size_t c : visible) {
        firsts.push_back(chunks_[c].first);
        counts.push_back(chunks_[c].count);
    }
    draw_ranges(firsts, counts, wireframe);
    return visible.size();
}

void GridMesh::draw_ranges(const std::vector<std::size_t>& firsts, const std::vector<std::size_t>& counts,
                           bool wireframe) const {
#if defined(OCEAN_GL_ES)
    // ES has no polygon mode and no multi-draw: one draw a range, of the triangles or of their
    // edges as lines (triangle_edges: the edges of indices [first, first + count) are at twice both).
    glBindVertexArray(wireframe ? edges_vao_.id() : vao_.id());
    const std::size_t scale = wireframe ? 2 : 1;
    for (std::size_t r = 0; r < firsts.size(); ++r)
        glDrawElements(wireframe ? GL_LINES : GL_TRIANGLES, GLsizei(scale * counts[r]), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(scale * firsts[r] * sizeof(unsigned)));
#else
    std::vector<GLsizei> sizes;
    std::vector<const void*> offsets;
    for (std::size_t r = 0; r < firsts.size(); ++r) {
        sizes.push_back(GLsizei(counts[r]));
        offsets.push_back(reinterpret_cast<const void*>(firsts[r] * sizeof(unsigned)));
    }
    glBindVertexArray(vao_.id());
    if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glMultiDrawElements(GL_TRIANGLES, sizes.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(firsts.size()));
    if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
#endif
}

void draw_grid(const GridMesh& grid, const ShaderProgram& program, const Camera& camera, float aspect,
               GpuTimers& timers, bool wireframe, float cull_margin) {
    const glm::mat4 view_projection = camera.projection(aspect) * camera.view();
    program.set("u_view_projection", view_projection);
    program.set("u_eye", camera.eye());
    GpuScope timed(timers, "ocean");
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program.id());
    if (cull_margin >= 0)
        grid.draw_visible(view_projection, cull_margin, wireframe);
    else
        grid.draw(wireframe);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace ocean
