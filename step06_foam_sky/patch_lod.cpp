#include "step06_foam_sky/patch_lod.hpp"

#include "common/frustum.hpp"
#include "common/grid.hpp"
#include "step06_foam_sky/tessellation.hpp"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace step06 {

namespace {
// What each drawn patch gives ocean_lod.vert: its corner, in patches from the grid's centre (a
// whole or half number: exact in float, so neighbours compute their shared edge alike), and the
// levels across its four edges.
struct PatchInstance {
    glm::vec2 corner;
    glm::vec4 neighbour_levels;  // across the edges i = 0, j = 0, i = L, j = L
};
}  // namespace

int patch_lod_level(double distance, double patch_size, double tess_scale) {
    const double wanted = tessellation_level(distance, patch_size, tess_scale);
    int level = 1;
    while (level < wanted && level < kMaxLodLevel) level *= 2;
    return level;
}

int snap_to_neighbour(int index, int level, int neighbour_level) {
    if (neighbour_level >= level) return index;
    const int step = level / neighbour_level;
    return index / step * step;
}

std::vector<int> patch_levels(int count, float size, float tess_scale, const PatchView& view) {
    std::vector<int> levels(std::size_t(count) * std::size_t(count));
    const glm::dvec2 midpoints[4] = {{0.0, 0.5}, {0.5, 0.0}, {1.0, 0.5}, {0.5, 1.0}};  // of the four edges, in patches
    for (int j = 0; j < count; ++j)
        for (int i = 0; i < count; ++i) {
            // The tessellator cuts each edge by the distance to its midpoint and the inside as
            // finely as the finest edge: so the distance to the nearest edge midpoint.
            const glm::dvec2 corner = glm::dvec2(view.grid_offset) + (glm::dvec2(i, j) - 0.5 * count) * double(size);
            double nearest = std::numeric_limits<double>::infinity();
            for (const glm::dvec2& m : midpoints) {
                const glm::dvec2 p = corner + m * double(size);
                nearest = std::min(nearest, glm::length(glm::dvec3(p.x, 0.0, p.y) - glm::dvec3(view.eye)));
            }
            levels[std::size_t(j) * std::size_t(count) + std::size_t(i)] = patch_lod_level(nearest, size, tess_scale);
        }
    return levels;
}

void PatchLod::build(int count, float size) {
    count_ = count;
    size_ = size;
    if (levels_[0].triangle_indices != 0) return;  // the meshes do not depend on the patches
    for (int k = 0; k < kLodLevels; ++k) {
        const int level = 1 << k;
        LevelMesh& m = levels_[std::size_t(k)];
        std::vector<glm::vec2> grid;  // (i, j), row by row along i: grid_triangles' order
        for (int j = 0; j <= level; ++j)
            for (int i = 0; i <= level; ++i) grid.emplace_back(float(i), float(j));
        const std::vector<unsigned> triangles = ocean::grid_triangles({1.0f, 1.0f}, level, level).indices;
        const std::vector<unsigned> edges = ocean::triangle_edges(triangles);
        m.grid = ocean::make_buffer();
        ocean::buffer_data(m.grid, GLsizeiptr(grid.size() * sizeof(glm::vec2)), grid.data(), GL_STATIC_DRAW);
        m.instances = ocean::make_buffer();
        // Two vertex arrays alike but for their indices: the triangles, or their edges as lines.
        m.vao = ocean::make_vertex_array();
        m.edges_vao = ocean::make_vertex_array();
        for (const ocean::VertexArray* vao : {&m.vao, &m.edges_vao}) {
            ocean::vertex_attribute(*vao, 0, m.grid, 2, sizeof(glm::vec2));
            ocean::instance_attribute(*vao, 1, m.instances, 2, sizeof(PatchInstance), offsetof(PatchInstance, corner));
            ocean::instance_attribute(*vao, 2, m.instances, 4, sizeof(PatchInstance),
                                      offsetof(PatchInstance, neighbour_levels));
        }
        // Index buffers are made indices before they hold data (element_buffer says why).
        m.triangles = ocean::make_buffer();
        ocean::element_buffer(m.vao, m.triangles);
        ocean::buffer_data(m.triangles, GLsizeiptr(triangles.size() * sizeof(unsigned)), triangles.data(), GL_STATIC_DRAW);
        m.edges = ocean::make_buffer();
        ocean::element_buffer(m.edges_vao, m.edges);
        ocean::buffer_data(m.edges, GLsizeiptr(edges.size() * sizeof(unsigned)), edges.data(), GL_STATIC_DRAW);
        m.triangle_indices = GLsizei(triangles.size());
        m.edge_indices = GLsizei(edges.size());
    }
}

int PatchLod::draw(const ocean::ShaderProgram& mesh, const PatchView& view, float tess_scale, bool wireframe) {
    const std::vector<int> levels = patch_levels(count_, size_, tess_scale, view);
    const auto level_at = [&](int i, int j, int fallback) {
        if (i < 0 || j < 0 || i >= count_ || j >= count_) return fallback;  // the grid's edge: no neighbour
        return levels[std::size_t(j) * std::size_t(count_) + std::size_t(i)];
    };
    // The patches that may be in view, sorted by level.
    const std::vector<glm::vec4> planes = ocean::frustum_planes(view.view_projection);
    const float margin = view.max_displacement;
    std::array<std::vector<PatchInstance>, kLodLevels> by_level;
    for (int j = 0; j < count_; ++j)
        for (int i = 0; i < count_; ++i) {
            const glm::vec2 corner = glm::vec2(float(i), float(j)) - 0.5f * float(count_);
            const glm::vec2 lo = view.grid_offset + corner * size_, hi = lo + size_;
            if (ocean::box_outside_frustum(planes, {lo.x - margin, -margin, lo.y - margin},
                                           {hi.x + margin, margin, hi.y + margin}))
                continue;
            const int level = level_at(i, j, 1);
            const glm::vec4 neighbours(level_at(i - 1, j, level), level_at(i, j - 1, level), level_at(i + 1, j, level),
                                       level_at(i, j + 1, level));
            by_level[std::size_t(std::log2(level) + 0.5)].push_back({corner, neighbours});
        }
    int drawn = 0;
    for (int k = 0; k < kLodLevels; ++k) {
        const std::vector<PatchInstance>& patches = by_level[std::size_t(k)];
        if (patches.empty()) continue;
        const LevelMesh& m = levels_[std::size_t(k)];
        ocean::buffer_data(m.instances, GLsizeiptr(patches.size() * sizeof(PatchInstance)), patches.data(), GL_STREAM_DRAW);
        mesh.set("u_level", float(1 << k));
        glBindVertexArray(wireframe ? m.edges_vao.id() : m.vao.id());
        glDrawElementsInstanced(wireframe ? GL_LINES : GL_TRIANGLES, wireframe ? m.edge_indices : m.triangle_indices,
                                GL_UNSIGNED_INT, nullptr, GLsizei(patches.size()));
        drawn += int(patches.size());
    }
    return drawn;
}

}  // namespace step06
