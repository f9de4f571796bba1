#version 450 core
// Normals per pixel from the slope maps (the spectral derivatives i k h~), or, as the notes' 4.2
// suggests, from finite differences of the height map; then step03's light.
#include "ocean_maps.glsl"
#include "gerstner.glsl"
#include "step03_lighting/shaders/lighting.glsl"
#include "srgb.glsl"

#ifndef NORMALS
#define NORMALS 0  // 0: slope maps, 1: finite differences of the height map
#endif
#ifndef SEA
#define SEA 0  // 0: the FFT's maps, 1: one Gerstner wave (gerstner.glsl), exact at every pixel
#endif

in vec3 v_world_position;
in vec2 v_uv;
in vec2 v_rest_xz;
out vec4 out_color;

uniform vec3 u_eye;
uniform bool u_wireframe;
uniform vec3 u_background;  // linear
uniform float u_patch_size;
uniform int u_resolution;
uniform vec4 u_gerstner;
uniform float u_gerstner_steepness, u_gerstner_phase;

void main() {
    if (u_wireframe) {
        out_color = vec4(0.75, 0.9, 1.0, 1.0);
        return;
    }
#if SEA == 1
    MapSample wave = gerstner_wave(v_rest_xz, u_gerstner, u_gerstner_steepness, u_gerstner_phase);
    vec4 displacement = wave.displacement, slopes = wave.slopes;
#else
    vec4 displacement = texture(u_displacement, vec3(v_uv, 0.0));
    vec4 slopes = texture(u_slopes, vec3(v_uv, 0.0));
#endif
#if NORMALS == 1 && SEA == 0
    // One texel each way: dh/dx ~ (h(x + d) - h(x - d)) / 2d with d = L / N.
    float texel = 1.0 / float(u_resolution);
    float spacing = u_patch_size * texel;
    slopes.x = (texture(u_displacement, vec3(v_uv + vec2(texel, 0.0), 0.0)).y -
                texture(u_displacement, vec3(v_uv - vec2(texel, 0.0), 0.0)).y) / (2.0 * spacing);
    slopes.y = (texture(u_displacement, vec3(v_uv + vec2(0.0, texel), 0.0)).y -
                texture(u_displacement, vec3(v_uv - vec2(0.0, texel), 0.0)).y) / (2.0 * spacing);
#endif
    vec3 normal = choppy_normal(displacement, slopes);
    LightTerms t = light_terms(normal, normalize(u_eye - v_world_position));
    vec3 colour = t.ambient + t.diffuse + t.specular;
    float fade = exp(-0.002 * length(v_world_position - u_eye));
    out_color = vec4(linear_to_srgb(mix(u_background, colour, fade)), 1.0);
}
