#version 450 core
// step06's shading pass (step06_foam_sky/shaders/ocean_shade.glsl) as a compute shader, a thread a
// pixel. A compute shader has no 2 x 2 quads, so every texture level is given, not derived
// (EXPLICIT_LEVELS: cascades_visible.glsl reads each piece at its own footprint's level).
#define EXPLICIT_LEVELS 1
#define UNIT_GBUFFER_DEPTH 8  // main.cpp's kDepthUnit
// Included first: it enables an extension, which must come before any declaration.
#include "step06_foam_sky/shaders/ocean_shade.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D u_depth;  // the mesh's depth: 1 where it drew no sea
layout(rgba16f, binding = 0) writeonly uniform image2D u_scene;  // the HDR target, the screen's size

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(u_scene))) || texelFetch(u_depth, pixel, 0).r >= 1.0) return;
    imageStore(u_scene, pixel, shade_sea_pixel(pixel));
}
