#version 450 core
// Per-pixel normals from the fBm sum at this pixel's point of the plane (the short waves are far
// smaller than a grid cell), lit with step03's light.
#include "fbm.glsl"
#include "step03_lighting/shaders/lighting.glsl"
#include "srgb.glsl"

#ifndef VIEW
#define VIEW 0  // VIEW_* below, in the order of main.cpp's `view` choices
#endif
#define VIEW_LIT 0
#define VIEW_DIFFUSE 1
#define VIEW_SPECULAR 2
#define VIEW_NORMALS 3

in vec3 v_world_position;
in vec3 v_normal;
in vec2 v_rest_xz;
out vec4 out_color;

uniform vec3 u_eye;
uniform bool u_wireframe;
uniform vec3 u_background;  // linear

void main() {
    if (u_wireframe) {
        out_color = vec4(0.75, 0.9, 1.0, 1.0);
        return;
    }
    vec3 normal = fbm_normal(fbm_height_gradient(v_rest_xz).yz);
#if VIEW == VIEW_NORMALS
    out_color = vec4(0.5 * normal + 0.5, 1.0);
#else
    LightTerms t = light_terms(normal, normalize(u_eye - v_world_position));
#if VIEW == VIEW_DIFFUSE
    vec3 colour = t.diffuse;
#elif VIEW == VIEW_SPECULAR
    vec3 colour = t.specular;
#else
    vec3 colour = t.ambient + t.diffuse + t.specular;
#endif
    float fade = exp(-0.004 * length(v_world_position - u_eye));
    out_color = vec4(linear_to_srgb(mix(u_background, colour, fade)), 1.0);
#endif
}
