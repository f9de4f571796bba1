#version 450 core
// Per-pixel lighting evaluates the normal again at this pixel's own point of the plane, so
// detail smaller than a triangle still catches the light; per-vertex lighting only blends the
// three corner colours (Gouraud shading).
#include "surface.glsl"
#include "srgb.glsl"

#ifndef PER_PIXEL
#define PER_PIXEL 1
#endif

in vec3 v_world_position;
in vec3 v_normal;
in vec3 v_vertex_colour;
in vec2 v_rest_xz;
out vec4 out_color;

uniform vec3 u_eye;
uniform bool u_wireframe;
uniform vec3 u_background;  // linear; the sea fades into it with distance

void main() {
    if (u_wireframe) {
        out_color = vec4(0.75, 0.9, 1.0, 1.0);
        return;
    }
#if PER_PIXEL
    vec3 normal = surface_normal(surface_height_gradient(v_rest_xz).yz);
    vec3 colour = surface_colour(v_rest_xz, normal, v_world_position, u_eye);
#else
    vec3 colour = v_vertex_colour;
#endif
#if VIEW >= VIEW_NORMALS
    float fade = 1.0;  // diagnostic views show their values undimmed
#else
    float fade = exp(-0.004 * length(v_world_position - u_eye));
#endif
    out_color = vec4(linear_to_srgb(mix(u_background, colour, fade)), 1.0);
}
