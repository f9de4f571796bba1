#version 450 core
// Places each generated vertex: its rest position from the patch corners, then the summed
// displacement of all cascades.
layout(quads, equal_spacing, ccw) in;
#include "cascades.glsl"

in vec2 te_rest_xz[];

uniform mat4 u_view_projection;
uniform vec3 u_eye;

out vec3 v_world_position;
out vec2 v_rest_xz;
out float v_level;  // for the wireframe view coloured by tessellation level

void main() {
    vec2 bottom = mix(te_rest_xz[0], te_rest_xz[1], gl_TessCoord.x);
    vec2 top = mix(te_rest_xz[3], te_rest_xz[2], gl_TessCoord.x);
    v_rest_xz = mix(bottom, top, gl_TessCoord.y);
    // Far away, a coarser mip of the displacement: the tessellation could not carry the detail.
    float lod = clamp(log2(length(vec3(v_rest_xz.x, 0.0, v_rest_xz.y) - u_eye) / 60.0), 0.0, 6.0);
    v_world_position = vec3(v_rest_xz.x, 0.0, v_rest_xz.y) + total_displacement(v_rest_xz, lod).xyz;
    v_level = gl_TessLevelInner[0];
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
