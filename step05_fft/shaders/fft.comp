#version 450 core
// Chapter 4.4: the inverse FFT along one axis of every line of every field of every cascade, in
// one dispatch: workgroup (line, layer) loads its N values into shared memory, runs all log2 N
// radix-2 Stockham stages there, and writes the line back. Two dispatches (x, then z) make the
// 2D transform. Stockham reorders as it goes, so no bit-reversal pass is needed:
//     stage p = 1, 2, 4 ... N/2, thread t < N/2, k = t mod p:
//     u0 = x[t], u1 = x[t + N/2] e^{+i pi k / p},  y[2t - k] = u0 + u1,  y[2t - k + p] = u0 - u1
// The result is sum_m X[m] e^{+2 pi i m n / N}, unnormalised, like FFTW_BACKWARD.
#ifndef FFT_SIZE
#define FFT_SIZE 256  // N: a compile-time variant per resolution (it sets the workgroup size)
#endif
layout(local_size_x = FFT_SIZE / 2) in;
#include "ocean_layout.glsl"

layout(std430, binding = 0) buffer Source { vec2 source[]; };
layout(std430, binding = 1) buffer Target { vec2 target[]; };  // may be the source buffer

uniform int u_axis;  // 0: along x (rows), 1: along z (columns)

shared vec2 lines[2][FFT_SIZE];

const float PI = 3.14159265358979;

int element(int layer, int line, int e) {
    int base = layer * FFT_SIZE * FFT_SIZE;
    return u_axis == 0 ? base + line * FFT_SIZE + e : base + e * FFT_SIZE + line;
}

void main() {
    int line = int(gl_WorkGroupID.x), layer = int(gl_WorkGroupID.y);  // layer = cascade * 4 + field
    int t = int(gl_LocalInvocationID.x);
    const int half_size = FFT_SIZE / 2;
    lines[0][t] = source[element(layer, line, t)];
    lines[0][t + half_size] = source[element(layer, line, t + half_size)];
    barrier();

    int from = 0;
    for (int p = 1; p < FFT_SIZE; p <<= 1) {
        int k = t & (p - 1);
        float angle = PI * float(k) / float(p);
        vec2 u0 = lines[from][t];
        vec2 u1 = complex_multiply(lines[from][t + half_size], vec2(cos(angle), sin(angle)));
        int out_index = (t << 1) - k;
        lines[1 - from][out_index] = u0 + u1;
        lines[1 - from][out_index + p] = u0 - u1;
        from = 1 - from;
        barrier();
    }
    target[element(layer, line, t)] = lines[from][t];
    target[element(layer, line, t + half_size)] = lines[from][t + half_size];
}
