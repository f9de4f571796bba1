#version 450 core
// evolve.comp as a fragment pass (fragment_simulation.cpp): one fragment per mode of an N x N
// spectrum, writing its four packed spectra into two textures (mode.glsl: the same formulas).
// The phase omega t comes reduced modulo 2 pi from the CPU, in double there: ES has no doubles.
#include "ocean_layout.glsl"
#include "mode.glsl"

uniform sampler2D u_h0;     // (h0(k), h0(-k))
uniform sampler2D u_phase;  // omega(k) t mod 2 pi
uniform float u_patch_size;

layout(location = 0) out vec4 spectra_01;  // (h + i Dx, Dz + i dh/dx)
layout(location = 1) out vec4 spectra_23;  // (dh/dz + i dDx/dx, dDz/dz + i dDx/dz)

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 h0 = texelFetch(u_h0, texel, 0);
    vec2 h = evolve_mode(h0.xy, h0.zw, texelFetch(u_phase, texel, 0).r);
    vec2 pairs[4] = packed_pairs(h, wave_vector(texel, u_n, u_patch_size));
    spectra_01 = vec4(pairs[0], pairs[1]);
    spectra_23 = vec4(pairs[2], pairs[3]);
}
