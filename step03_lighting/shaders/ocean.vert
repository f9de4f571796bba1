#version 450 core
// Lifts each vertex like step02, and computes its normal. With per-vertex lighting
// (PER_PIXEL 0) it also computes the colour here, which the rasteriser then interpolates
// across each triangle.
#include "surface.glsl"

#ifndef PER_PIXEL
#define PER_PIXEL 1
#endif

layout(location = 0) in vec2 a_rest_xz;

uniform mat4 u_view_projection;
uniform vec3 u_eye;

out vec3 v_world_position;  // these three are also captured by the read-back test
out vec3 v_normal;
out vec3 v_vertex_colour;
out vec2 v_rest_xz;

void main() {
    vec3 height_gradient = surface_height_gradient(a_rest_xz);
    v_world_position = vec3(a_rest_xz.x, height_gradient.x, a_rest_xz.y);
    v_normal = surface_normal(height_gradient.yz);
#if PER_PIXEL
    v_vertex_colour = vec3(0.0);
#else
    v_vertex_colour = surface_colour(a_rest_xz, v_normal, v_world_position, u_eye);
#endif
    v_rest_xz = a_rest_xz;
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
