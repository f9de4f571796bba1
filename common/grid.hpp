// The water plane: (x_quads+1)(z_quads+1) vertices on a flat grid centred on the origin, each
// holding only its rest position (x, z); the vertex shader lifts it into a wave.
#pragma once

#include "common/gl.hpp"
#include "common/params.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <vector>

namespace ocean {

// Rest positions, row by row along x; size in metres, counts in quads.
std::vector<glm::vec2> grid_positions(glm::vec2 size, int x_quads, int z_quads);

// The triangles come in square chunks of up to kChunkQuads x kChunkQuads quads, so that the
// chunks outside the view can be left out of the draw: a plane reaching the horizon is mostly
// behind and beside the camera, and a software rasteriser pays for every vertex it transforms.
constexpr int kChunkQuads = 32;
struct GridChunk {
    std::size_t first = 0, count = 0;  // its indices
    glm::vec2 lo{0}, hi{0};            // rest positions it spans (x, z), metres
};
struct GridTriangles {
    std::vector<unsigned> indices;  // two counter-clockwise (seen from +y) triangles a quad, chunk by chunk
    std::vector<GridChunk> chunks;
};
GridTriangles grid_triangles(glm::vec2 size, int x_quads, int z_quads);
// The chunks of which some part may be seen: each chunk's box, lifted from rest by up to
// `margin` metres in every direction (the waves' largest displacement), against the frustum.
std::vector<std::size_t> visible_chunks(const std::vector<GridChunk>& chunks, const glm::mat4& view_projection,
                                        float margin);

// The edges of triangles (three indices each) as lines (two indices each): a, b, b, c, c, a. The
// wireframe where there is no polygon mode (ES); triangle t's edges are at indices 6t to 6t + 5.
std::vector<unsigned> triangle_edges(const std::vector<unsigned>& triangles);

class GridMesh {
public:
    void build(glm::vec2 size, int x_quads, int z_quads);
    // GL_TRIANGLES (attribute 0 is vec2 (x, z)), or only their edges when `wireframe`.
    void draw(bool wireframe = false) const;
    // Only the chunks visible_chunks keeps; returns how many were drawn.
    std::size_t draw_visible(const glm::mat4& view_projection, float margin, bool wireframe = false) const;
    int vertex_count() const { return vertex_count_; }
    std::size_t chunk_count() const { return chunks_.size(); }
    GLuint vertex_buffer() const { return vertices_.id(); }
    GLuint vertex_array() const { return vao_.id(); }

private:
    // Index ranges [first, first + count) of the triangles, in one draw where the profile allows.
    void draw_ranges(const std::vector<std::size_t>& firsts, const std::vector<std::size_t>& counts, bool wireframe) const;

    VertexArray vao_;
    Buffer vertices_, indices_;
#if defined(OCEAN_GL_ES)
    VertexArray edges_vao_;  // the wireframe: ES has no polygon mode (triangle_edges)
    Buffer edges_;
#endif
    int vertex_count_ = 0;
    GLsizei index_count_ = 0;
    std::vector<GridChunk> chunks_;
};

class Camera;
class GpuTimers;
class ShaderProgram;

// Draws `grid` with `program` as `camera` sees it (u_view_projection and u_eye set), depth-tested,
// timed as the "ocean" pass: the last lines of every grid-based step's render(). With
// `cull_margin` >= 0 (metres: the most any vertex moves from rest), only the chunks that may be in
// view are drawn.
void draw_grid(const GridMesh& grid, const ShaderProgram& program, const Camera& camera, float aspect,
               GpuTimers& timers, bool wireframe, float cull_margin = -1);

// The grid's size and resolution as parameters (plane_size, x_quads, z_quads), for the steps that
// draw one plane.
class GridParams {
public:
    // The defaults: a plane of `size` metres with `quads` cells a side.
    explicit GridParams(float size = 80, int quads = 160) : plane_size_(size), x_quads_(quads), z_quads_(quads) {}

    void declare(ParamRegistry& p) {
        const auto grid_group = p.group("grid", &changes_);
        p.add_float("plane_size", &plane_size_, 1, 5000, "side of the square plane, metres");
        p.add_int("x_quads", &x_quads_, 1, 2048, "grid cells along x (vertices: x_quads + 1)");
        p.add_int("z_quads", &z_quads_, 1, 2048, "grid cells along z (vertices: z_quads + 1)");
    }

    // Rebuilds the mesh only when its size or resolution changed.
    void update(GridMesh& grid) {
        if (made_for_ == changes_.value) return;
        grid.build({plane_size_, plane_size_}, x_quads_, z_quads_);
        made_for_ = changes_.value;
    }

    int triangle_count() const { return 2 * x_quads_ * z_quads_; }

private:
    float plane_size_;
    int x_quads_, z_quads_;
    Generation changes_;
    unsigned made_for_ = 0;
};

}  // namespace ocean
