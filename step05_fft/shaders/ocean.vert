#version 450 core
// Moves each grid vertex by the simulated displacement (l Dx, h, l Dz). The maps tile: the
// texture coordinate is the rest position over the patch size, and the textures repeat.
// With SEA 1 (sea=gerstner) the displacement is one Gerstner wave's, in closed form, instead.
#include "ocean_maps.glsl"
#include "gerstner.glsl"

#ifndef SEA
#define SEA 0  // 0: the FFT's maps, 1: one Gerstner wave (gerstner.glsl)
#endif

layout(location = 0) in vec2 a_rest_xz;

uniform mat4 u_view_projection;
uniform float u_patch_size;
uniform vec4 u_gerstner;  // sea=gerstner: (d.x, d.z, k, A)
uniform float u_gerstner_steepness, u_gerstner_phase;

out vec3 v_world_position;
out vec2 v_uv;
out vec2 v_rest_xz;

void main() {
    v_uv = map_uv(a_rest_xz, u_patch_size);
    v_rest_xz = a_rest_xz;
#if SEA == 1
    vec4 displacement = gerstner_wave(a_rest_xz, u_gerstner, u_gerstner_steepness, u_gerstner_phase).displacement;
#else
    vec4 displacement = textureLod(u_displacement, vec3(v_uv, 0.0), 0.0);
#endif
    v_world_position = vec3(a_rest_xz.x, 0.0, a_rest_xz.y) + displacement.xyz;
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
