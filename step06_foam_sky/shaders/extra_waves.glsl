// Extra waves on a grid of their own (extra_waves.hpp), in step05's layout, so that they add to the
// cascades' sums term by term: the displacement, the slopes, and through them the normal and the
// Jacobian (foam where they fold). EXTRA_WAVES 0 (a sea given none) compiles none of it.
#ifndef EXTRA_WAVES
#define EXTRA_WAVES 0
#endif
#if EXTRA_WAVES
#include "step06_foam_sky/texture_units.h"

layout(binding = UNIT_EXTRA_DISPLACEMENT) uniform sampler2D u_extra_displacement;  // (l Dx, h, l Dz, l dDx/dz)
layout(binding = UNIT_EXTRA_SLOPES) uniform sampler2D u_extra_slopes;              // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)
uniform vec2 u_extra_first_cell;  // cell (0, 0)'s centre, metres from the world origin
uniform float u_extra_cell;       // metres

// Bilinear between the four cell centres around rest position p (texelFetch: float textures
// are not filterable everywhere); nothing outside the grid, so waves that fade out towards its
// edges join the sea without a seam.
vec4 extra_map_at(sampler2D map, vec2 p) {
    int n = textureSize(map, 0).x;
    vec2 q = (p - u_extra_first_cell) / u_extra_cell;
    if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, vec2(float(n - 1))))) return vec4(0.0);
    ivec2 i = ivec2(floor(q));
    vec2 f = q - vec2(i);
    vec4 bottom = mix(texelFetch(map, i, 0), texelFetch(map, i + ivec2(1, 0), 0), f.x);
    vec4 top = mix(texelFetch(map, i + ivec2(0, 1), 0), texelFetch(map, i + ivec2(1, 1), 0), f.x);
    return mix(bottom, top, f.y);
}
vec4 extra_displacement_at(vec2 p) { return extra_map_at(u_extra_displacement, p); }
vec4 extra_slopes_at(vec2 p) { return extra_map_at(u_extra_slopes, p); }
#endif
