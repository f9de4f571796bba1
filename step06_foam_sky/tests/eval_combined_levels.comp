#version 450 core
// Evaluates combined_levels.glsl at given offsets from the levels' centre, for the read-back test
// against combined_levels.hpp.
layout(local_size_x = 64) in;
#include "step06_foam_sky/shaders/combined_levels.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec2 offsets[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float texels[]; };

uniform int u_count;
uniform float u_texels;
uniform float u_finest_texel;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    texels[i] = combined_level_texel(offsets[i], u_texels, u_finest_texel);
}
