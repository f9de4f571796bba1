// Extra waves on a grid of their own, added term by term to the cascades' maps: waves the spectrum
// does not hold (made by something on the water, say), as two maps in step05's layout over n x n
// cells placed anywhere in the world. Where EXTRA_WAVES is 1 the sea's shaders add them to the
// cascades' sums (extra_waves.glsl): the mesh's displacement, the pixels' slopes, and through them
// the normal and the Jacobian that makes foam. A sea given none compiles none of it (EXTRA_WAVES
// 0): its shaders are the cascades' alone.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace step06 {

// One frame's extra waves on the CPU: per cell (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz,
// l dDx/dx, l dDz/dz), row (z) major, cell (0, 0)'s centre at `first_cell` (world x, z).
struct ExtraWaveMaps {
    int n = 0;
    double cell = 0;  // metres
    glm::dvec2 first_cell{0.0};
    std::vector<float> displacement, slopes;  // n * n * 4 each
};

// The maps at rest position `rest` (world x, z) as extra_waves.glsl's extra_map_at reads them, in
// double: bilinear between the four cell centres around it, zero outside the grid (and for a grid
// of fewer than 2 x 2 cells). The CPU reference of that read, and the extra waves' part of the
// surface for anything on the CPU that floats on it.
struct ExtraWaveSample {
    glm::dvec4 displacement{0.0};  // (l Dx, h, l Dz, l dDx/dz)
    glm::dvec4 slopes{0.0};        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)
};
ExtraWaveSample extra_waves_at(const ExtraWaveMaps& maps, glm::dvec2 rest);

// The same on the GPU: two RGBA32F textures read texel by texel (bilinear in the shader, as in
// every profile float textures may be fetched but not always filtered).
class ExtraWaves {
public:
    void upload(const ExtraWaveMaps& maps);
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
