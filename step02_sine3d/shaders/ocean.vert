#version 450 core
// Lifts each grid vertex from rest (x, 0, z) to (x, h(x, z, t), z).
#include "waves.glsl"
#include "ripple.glsl"

layout(location = 0) in vec2 a_rest_xz;

uniform mat4 u_view_projection;

out vec3 v_world_position;  // also captured by transform feedback in the read-back test

void main() {
    v_world_position = vec3(a_rest_xz.x, wave_height(a_rest_xz), a_rest_xz.y);
    if (u_ripple.w != 0.0) v_world_position.y += ripple_height(a_rest_xz);  // ripple_amplitude: 0 is none
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
