#version 450 core
// Evaluates sky_horizon.glsl at given directions, for the read-back test: its coordinate (against
// sky.hpp's horizon_coordinate), the fog's colour from the table, and the cube fetch the table
// stands for.
layout(local_size_x = 64) in;
#include "step06_foam_sky/shaders/sky_horizon.glsl"

layout(binding = UNIT_SKY) uniform samplerCube u_sky;
layout(std430, binding = 0) readonly buffer Inputs { vec4 directions[]; };
// Per direction: (coordinate, 0, 0, 0), the table's colour, the cube's colour.
layout(std430, binding = 1) writeonly buffer Outputs { vec4 results[]; };

uniform int u_count;
uniform float u_lod;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    vec3 d = directions[i].xyz;
    results[3 * i] = vec4(horizon_coordinate(d.xz), 0.0, 0.0, 0.0);
    results[3 * i + 1] = vec4(horizon_colour(d), 0.0);
    results[3 * i + 2] = textureLod(u_sky, normalize(vec3(d.x, 0.0, d.z)), u_lod);
}
