#version 450 core
// Lifts each vertex by the fBm cascades; the exact normal goes along for the read-back test.
#include "fbm.glsl"

layout(location = 0) in vec2 a_rest_xz;

uniform mat4 u_view_projection;

out vec3 v_world_position;  // these two are captured by the read-back test
out vec3 v_normal;
out vec2 v_rest_xz;

void main() {
    vec3 height_gradient = fbm_height_gradient(a_rest_xz);
    v_world_position = vec3(a_rest_xz.x, height_gradient.x, a_rest_xz.y);
    v_normal = fbm_normal(height_gradient.yz);
    v_rest_xz = a_rest_xz;
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
