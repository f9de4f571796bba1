// Waves a later chapter adds to the sea on a grid of its own (step08's wake around the boat): two
// maps in step05's layout over n x n cells, placed in the world. The sea's shaders add them to
// the cascades where LOCAL_WAVES is 1 (local_waves.glsl): the mesh's displacement, the pixels'
// slopes, and the Jacobian that makes foam. step06 itself adds none (LOCAL_WAVES 0), so its
// pictures do not change.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step06 {

// One frame's local waves on the CPU: per cell (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz,
// l dDx/dx, l dDz/dz), row (z) major, cell (0, 0)'s centre at `first_cell` (world x, z).
struct LocalWaveMaps {
    int n = 0;
    double cell = 0;  // metres
    glm::dvec2 first_cell{0.0};
    std::vector<float> displacement, slopes;  // n * n * 4 each
};

// The same on the GPU: two RGBA32F textures read texel by texel (bilinear in the shader, as in
// every profile float textures may be fetched but not always filtered).
class LocalWaves {
public:
    void upload(const LocalWaveMaps& maps);
    bool empty() const { return n_ == 0; }
    // The textures on their units (texture_units.h) and where the grid is from `world_origin`
    // (the sea's, Sea::world_origin: x, z).
    void bind(const ocean::ShaderProgram& p, glm::dvec2 world_origin) const;

private:
    ocean::Texture displacement_, slopes_;
    int n_ = 0;
    double cell_ = 0;
    glm::dvec2 first_cell_{0.0};
};

}  // namespace step06
