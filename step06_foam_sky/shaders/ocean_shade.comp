#version 450 core
// Deferred shading's second pass as a compute shader (ocean_shade.glsl), a thread a pixel. On a
// GPU built for compute, fragment shaders run on the few units that can do graphics while a
// compute shader runs on all of them (an H100 runs vertex and fragment shaders on 2 of its 66
// texture processing clusters, NVIDIA's white paper says): the same shading, many times faster
// there (docs/performance.md). A compute shader has no 2 x 2 quads, so every texture level is
// given, not derived (cascades_visible.glsl, SHADING_IN_COMPUTE).
#define SHADING_IN_COMPUTE 1
// Included first: it enables an extension, which must come before any declaration.
#include "ocean_shade.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D u_depth;  // the mesh's depth: 1 where it drew no sea
layout(rgba16f, binding = 0) writeonly uniform image2D u_scene;  // the HDR target, the screen's size

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(u_scene))) || texelFetch(u_depth, pixel, 0).r >= 1.0) return;
    imageStore(u_scene, pixel, shade_sea_pixel(pixel));
}
