#version 450 core
// --export: the summed surface (what foam.comp sees) at the texel centres of one foam level's
// window, in the world's order (row j is the window's z cell origin.z + j), so that the exported
// height, Jacobian and foam lie on one grid.
layout(local_size_x = 8, local_size_y = 8) in;
#include "cascades.glsl"

layout(rgba32f, binding = 0) writeonly uniform image2D u_displacement_out;  // (l Dx, h, l Dz, l dDx/dz)
layout(rgba32f, binding = 1) writeonly uniform image2D u_slopes_out;        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)

uniform int u_n;
uniform ivec2 u_origin;     // the window's first cell, counted from the world origin (CascadeView)
uniform float u_texel_size; // metres

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    if (id.x >= u_n || id.y >= u_n) return;
    vec2 p = (vec2(u_origin + id) + 0.5) * u_texel_size;
    vec4 displacement, slopes;
    surface_at(p, u_texel_size, displacement, slopes);
    imageStore(u_displacement_out, id, displacement);
    imageStore(u_slopes_out, id, slopes);
}
