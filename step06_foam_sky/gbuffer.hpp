// Deferred shading's first target (chapter 5's ocean pass in two halves): the tessellated mesh is
// drawn once with a shader that only records where each pixel meets the sea (ocean.frag), then
// every pixel the sea covers is shaded once by a full-screen pass (ocean_shade.frag).
//
// Why: the mesh's triangles near the horizon are slivers a few pixels tall. A rasteriser shades
// pixels in 2 x 2 quads (llvmpipe in blocks of 4 x 4), so a sliver's quads are mostly pixels
// outside it, shaded and thrown away: at 1280 x 720 the default view ran the shading 1.06 million
// times for 0.58 million pixels (GL_ARB_pipeline_statistics_query). Recording is cheap; the
// shading (a dozen texture fetches) now runs once per pixel.
#pragma once

#include "common/gl.hpp"

#include <glm/vec2.hpp>

namespace step06 {

class GBuffer {
public:
    // (Re)makes the targets for a new size; `depth` is the scene's depth texture, shared so the
    // shading pass can test against the mesh's depth.
    void resize(glm::ivec2 size, GLuint depth);
    void bind() const;  // as the draw target, with the depth buffer
    // RGBA32F: the displaced surface point (world metres) and the choppy normal's cross term
    // l dDx/dz from the vertices (ocean.frag; the tessellation level in the view coloured by it).
    GLuint world_texture() const { return world_.id(); }
    // RGBA32UI: the rest position (float bits) and its screen derivatives d/dx, d/dy (half pairs).
    GLuint rest_texture() const { return rest_.id(); }

private:
    glm::ivec2 size_{0};
    GLuint depth_ = 0;
    ocean::Texture world_, rest_;
    ocean::Framebuffer target_;
};

}  // namespace step06
