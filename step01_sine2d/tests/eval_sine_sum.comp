#version 450 core
// Evaluates step01's sum_of_sines at evenly spaced x, for the read-back test.
layout(local_size_x = 64) in;
#include "step01_sine2d/shaders/sine_sum.glsl"

layout(std430, binding = 0) writeonly buffer Samples { vec2 samples[]; };  // (x, f(x))

uniform vec2 u_x_range;
uniform int u_sample_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_sample_count) return;
    float x = mix(u_x_range.x, u_x_range.y, float(i) / float(u_sample_count - 1));
    samples[i] = vec2(x, sum_of_sines(x));
}
