#version 450 core
// Deferred shading, first pass (gbuffer.hpp): what each pixel sees of the sea, nothing more; the
// shading is ocean_shade.frag's. The derivatives of the rest position are taken here, on the
// triangle: in the shading pass a 2 x 2 quad may straddle a crest and the water behind it, and
// its differences would be meaningless.
#include "half_pack.glsl"
#include "level_colour.glsl"

#ifndef WIREFRAME
#define WIREFRAME 0  // 1: drawn as lines straight into the scene, coloured by tessellation level
#endif
#ifndef LEVEL_VIEW
#define LEVEL_VIEW 0  // 1: g_world.w holds the tessellation level, for the view that colours by it
#endif

in vec3 v_world_position;
in vec2 v_rest_xz;
in float v_cross_term;
in float v_level;

layout(location = 0) out vec4 g_world;  // the surface point; the cross term (or the level)
layout(location = 1) out uvec4 g_rest;  // rest position, d/dx and d/dy of it

void main() {
#if WIREFRAME
    g_world = vec4(level_colour(v_level) * 1.5, 1.0);  // a colour, through the tonemapper: kept in range
    return;
#endif
    // The choppy normal's cross term l dDx/dz from the vertices, not fetched per pixel: it is a
    // product of slopes in the normal (choppy_normal), second order where the slopes are small,
    // and reading it per pixel cost four fetches a pixel, 15 % of the ocean pass on llvmpipe
    // (docs/performance.md). The slopes, first order, are still read per pixel.
    g_world = vec4(v_world_position, LEVEL_VIEW == 1 ? v_level : v_cross_term);
    // Coarse (one per 2 x 2 quad), as the filtering expects: every decision that follows from
    // them is then the same for the four pixels of a quad.
    g_rest = uvec4(floatBitsToUint(v_rest_xz), pack_halves(dFdxCoarse(v_rest_xz)), pack_halves(dFdyCoarse(v_rest_xz)));
}
