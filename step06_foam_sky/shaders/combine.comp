#version 450 core
// The cascades combined around the camera (combined_surface.hpp): each texel of each level holds
// the summed surface at its world position as a sample one texel wide sees it (cascades.glsl's
// surface_at, the foam's sampling). The mesh and the shading then read one level, not four
// cascades (combined_surface.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "cascades.glsl"

const int MAX_COMBINED_LEVELS = 12;
layout(rgba16f, binding = 0) writeonly uniform image2DArray u_displacement_levels;  // (l Dx, h, l Dz, l dDx/dz)
layout(rgba16f, binding = 1) writeonly uniform image2DArray u_slopes_levels;        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)

uniform int u_n;       // texels per side of a level
uniform int u_levels;
uniform ivec2 u_origin[MAX_COMBINED_LEVELS];       // each level's first cell, in its texels, from the world origin
uniform float u_texel_size[MAX_COMBINED_LEVELS];  // metres

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (id.x >= u_n || id.y >= u_n || id.z >= u_levels) return;
    float texel = u_texel_size[id.z];
    vec2 p = (vec2(u_origin[id.z] + id.xy) + 0.5) * texel;
    vec4 displacement, slopes;
    surface_at(p, texel, displacement, slopes);
    imageStore(u_displacement_levels, id, displacement);
    imageStore(u_slopes_levels, id, slopes);
}
