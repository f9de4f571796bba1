#version 450 core
// Places each generated vertex: its rest position from the patch corners, then the summed
// displacement of all cascades.
layout(quads, equal_spacing, ccw) in;
#include "cascades.glsl"

in vec2 te_rest_xz[];

uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform float u_tess_scale;  // the control shader's: level = tess_scale * patch / distance

out vec3 v_world_position;
out vec2 v_rest_xz;
out float v_cross_term;  // l dDx/dz: the choppy normal's cross term (ocean.frag says why per vertex)
out float v_level;       // for the views coloured by tessellation level

void main() {
    vec2 bottom = mix(te_rest_xz[0], te_rest_xz[1], gl_TessCoord.x);
    vec2 top = mix(te_rest_xz[3], te_rest_xz[2], gl_TessCoord.x);
    v_rest_xz = mix(bottom, top, gl_TessCoord.y);
    // Vertices at distance d are about patch / level = d / tess_scale apart: waves shorter than two
    // spacings would be sampled at random phases from vertex to vertex (aliasing), so each cascade
    // is read at the mip level that averages them away; their slopes still reach the pixels
    // (ocean_shade.frag reads them per pixel, and what a pixel cannot resolve becomes roughness). The
    // spacing is a function of the position alone, so two patches sharing an edge displace its
    // vertices alike and no crack opens.
    float spacing = length(vec3(v_rest_xz.x, 0.0, v_rest_xz.y) - u_eye) / u_tess_scale;
    vec4 displacement = displacement_at(v_rest_xz, 2.0 * spacing);
    v_world_position = vec3(v_rest_xz.x, 0.0, v_rest_xz.y) + displacement.xyz;
    v_cross_term = displacement.w;
    v_level = gl_TessLevelInner[0];
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
