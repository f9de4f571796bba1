#version 450 core
// Chapter 5.1 without tessellation shaders (ES 3.0, WebGL 2; patch_lod.hpp): a vertex of a patch
// cut on the CPU into u_level x u_level quads, placed and displaced as ocean.tese places and
// displaces the tessellator's, into the same G-buffer (ocean.frag).
#include "cascades.glsl"

layout(location = 0) in vec2 a_grid;              // the vertex in its patch: (i, j), 0 to u_level
layout(location = 1) in vec2 a_corner;            // the patch's corner, in patches from the grid's centre
layout(location = 2) in vec4 a_neighbour_levels;  // the levels across its edges i = 0, j = 0, i = L, j = L

uniform float u_level;           // this draw's patches' level L, a power of two
uniform vec2 u_grid_offset;      // the camera's x, z snapped to the patch size
uniform float u_tess_patch_size; // metres
uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform float u_tess_scale;  // level = tess_scale * patch / distance, as the tessellator's

out vec3 v_world_position;
out vec2 v_rest_xz;
out float v_cross_term;
out float v_level;

// Index i along an edge whose neighbour has `neighbour_level`: where that patch is coarser, the
// vertex moves down to its nearest vertex below (snap_to_neighbour, patch_lod.cpp), so both
// patches put the same vertices on the edge.
float snapped(float index, float neighbour_level) {
    float step = u_level / min(u_level, neighbour_level);
    return floor(index / step) * step;
}

void main() {
    vec2 g = a_grid;
    if (a_grid.x == 0.0) g.y = snapped(a_grid.y, a_neighbour_levels.x);
    if (a_grid.y == 0.0) g.x = snapped(a_grid.x, a_neighbour_levels.y);
    if (a_grid.x == u_level) g.y = snapped(a_grid.y, a_neighbour_levels.z);
    if (a_grid.y == u_level) g.x = snapped(a_grid.x, a_neighbour_levels.w);
    // (corner + g / L) in patches: g / L is the same float from both sides of an edge (the same
    // fraction, rounded once), and so is the sum, so the shared vertices are the same bits.
    v_rest_xz = u_grid_offset + (a_corner + g / u_level) * u_tess_patch_size;
    // As ocean.tese: each cascade at the mip level that averages away waves shorter than two
    // vertex spacings (about distance / tess_scale apart).
    float spacing = length(vec3(v_rest_xz.x, 0.0, v_rest_xz.y) - u_eye) / u_tess_scale;
    vec4 displacement = displacement_at(v_rest_xz, 2.0 * spacing);
    v_world_position = vec3(v_rest_xz.x, 0.0, v_rest_xz.y) + displacement.xyz;
    v_cross_term = displacement.w;
    v_level = u_level;
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
