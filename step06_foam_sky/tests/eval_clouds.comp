#version 450 core
// Evaluates step06's sky.glsl cloud pattern at given points, for the read-back test against
// sky.hpp (lattice_hash at integer points, clouds anywhere).
layout(local_size_x = 64) in;
#include "step06_foam_sky/shaders/sky.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec2 points[]; };
// Per point: (lattice_hash at floor(p), clouds(p)).
layout(std430, binding = 1) writeonly buffer Outputs { vec2 results[]; };

uniform int u_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    vec2 p = points[i];
    results[i] = vec2(lattice_hash(ivec2(floor(p))), clouds(p));
}
