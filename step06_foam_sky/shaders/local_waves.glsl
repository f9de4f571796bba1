// Waves a later chapter adds to the sea on a grid of its own (local_waves.hpp: step08's wake),
// in step05's layout, so that they add to the cascades' sums term by term: the displacement, the
// slopes, and through them the normal and the Jacobian (foam where they fold). LOCAL_WAVES 0
// (step06) compiles none of it.
#ifndef LOCAL_WAVES
#define LOCAL_WAVES 0
#endif
#if LOCAL_WAVES
#include "step06_foam_sky/texture_units.h"

layout(binding = UNIT_LOCAL_DISPLACEMENT) uniform sampler2D u_local_displacement;  // (l Dx, h, l Dz, l dDx/dz)
layout(binding = UNIT_LOCAL_SLOPES) uniform sampler2D u_local_slopes;              // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)
uniform vec2 u_local_first_cell;  // cell (0, 0)'s centre, metres from the world origin
uniform float u_local_cell;       // metres

// Bilinear between the four cell centres around rest position p (texelFetch: float textures
// are not filterable everywhere); nothing outside the grid, whose edges the absorbing layer has
// calmed.
vec4 local_map_at(sampler2D map, vec2 p) {
    int n = textureSize(map, 0).x;
    vec2 q = (p - u_local_first_cell) / u_local_cell;
    if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, vec2(float(n - 1))))) return vec4(0.0);
    ivec2 i = ivec2(floor(q));
    vec2 f = q - vec2(i);
    vec4 bottom = mix(texelFetch(map, i, 0), texelFetch(map, i + ivec2(1, 0), 0), f.x);
    vec4 top = mix(texelFetch(map, i + ivec2(0, 1), 0), texelFetch(map, i + ivec2(1, 1), 0), f.x);
    return mix(bottom, top, f.y);
}
vec4 local_displacement_at(vec2 p) { return local_map_at(u_local_displacement, p); }
vec4 local_slopes_at(vec2 p) { return local_map_at(u_local_slopes, p); }
#endif
