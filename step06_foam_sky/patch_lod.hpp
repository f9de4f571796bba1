// Chapter 5.1 without tessellation shaders (OpenGL ES 3.0, WebGL 2): the same patches around the
// camera (patch_grid.hpp), each cut on the CPU instead of by the tessellator. A patch is drawn at
// a level L, L x L quads, a power of two from 1 to 64: the tessellator's finest level for it (its
// inner level: the level of its nearest edge, tessellation.hpp), rounded up, so it is never
// coarser than the tessellated sea. There is one mesh per level, drawn once a frame for all the
// patches of that level (instanced: the mesh repeated, each copy given its patch's place and its
// four neighbours' levels as attributes that advance once a copy).
//
// Where two patches of different levels meet, the finer one has vertices the coarser one lacks.
// Displaced by the waves, such a vertex would not lie on the coarser patch's edge, and a crack
// would open. So on each edge the finer patch's vertices snap to the coarser one's (every
// (L / L_neighbour)-th, rounded down): the positions on a shared edge are then the same from
// both sides, bit for bit (ocean_lod.vert), and the surplus triangles collapse to nothing.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/patch_view.hpp"

#include <array>
#include <string>
#include <vector>

namespace step06 {

constexpr int kLodLevels = 7;      // levels 1, 2, 4, ..., 64 segments a side
constexpr int kMaxLodLevel = 64;   // the tessellator's largest level (GL's least maximum)

// The level a patch whose nearest edge midpoint is `distance` metres from the eye is drawn at: the
// tessellator's level there (tessellation_level), rounded up to a power of two.
int patch_lod_level(double distance, double patch_size, double tess_scale);

// Where index `index` (0 to level) along an edge of a patch of `level` lands when the neighbour
// across that edge has `neighbour_level`: unchanged where the neighbour is as fine or finer,
// otherwise rounded down to the neighbour's vertices (ocean_lod.vert's snapped()).
int snap_to_neighbour(int index, int level, int neighbour_level);

// Every patch's level, count x count, row by row (patch (i, j) at j * count + i), for `view`.
std::vector<int> patch_levels(int count, float size, float tess_scale, const PatchView& view);

class PatchLod {
public:
    // The shaders that draw it into the G-buffer: a vertex shader in place of the tessellation.
    static std::vector<std::string> mesh_shaders() {
        return {"step06_foam_sky/shaders/ocean_lod.vert", "step06_foam_sky/shaders/ocean.frag"};
    }

    // Called when patch_count or tess_patch_size changed; makes the meshes once.
    void build(int count, float size);
    // The patches that may be in view, one instanced draw per level, with `mesh` (ocean_lod.vert
    // and ocean.frag) in use; u_level is set for each draw. The triangles' edges as lines when
    // `wireframe`. Returns how many patches were drawn.
    int draw(const ocean::ShaderProgram& mesh, const PatchView& view, float tess_scale, bool wireframe);
    int patch_count() const { return count_ * count_; }

private:
    struct LevelMesh {
        ocean::Buffer grid, triangles, edges, instances;  // (i, j) vertices; indices; per-patch data
        ocean::VertexArray vao, edges_vao;
        GLsizei triangle_indices = 0, edge_indices = 0;
    };
    std::array<LevelMesh, kLodLevels> levels_;
    int count_ = 0;
    float size_ = 0;
};

}  // namespace step06
