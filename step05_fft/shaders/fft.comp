#version 450 core
// Chapter 4.4, the optimised FFT (fft=stockham4, the default; README section 3 derives it from
// fft_radix2.comp's plain form): the inverse FFT along one axis of every line of every field of
// every cascade, in one dispatch: workgroup (line, layer) loads its N values into shared memory, runs all stages
// there, and writes the line back. Two dispatches (x, then z) make the 2D transform. Stockham
// reorders as it goes, so no bit-reversal pass is needed. The stages are radix 4 (half as many
// as radix 2, so half the barriers and half the trips through shared memory), with one radix-2
// stage last when log2 N is odd (N = 128, 512). A stage of radix R and stride p (p = 1, R, R^2 ...)
// twiddles R inputs N / R apart and joins them with an R-point inverse DFT, written where the next
// stage reads them (fft.md, section 3, derives the indices; radix 4 needs no multiplication beyond
// the twiddles, its DFT's factors being 1, i, -1, -i). The twiddles come from a table of
// e^{+2 pi i m / N} computed once in double on the CPU (OceanSimulation::twiddles_), not from sin and
// cos per butterfly. The result is sum_m X[m] e^{+2 pi i m n / N}, unnormalised, like
// FFTW_BACKWARD.
// A workgroup holds LINES neighbouring lines, one per x of its threads (y is t). Along x a line's
// values are N apart in memory, so a workgroup of one column read 8 bytes from every 32-byte
// sector it touched; with neighbouring columns side by side in a warp, their reads of one row
// fill the sector (docs/performance.md: the column pass on a GPU).
#ifndef FFT_SIZE
#define FFT_SIZE 256  // N: a compile-time variant per resolution (it sets the workgroup size)
#endif
#ifndef LINES
#define LINES 4  // lines a workgroup: 2 LINES N values of 8 bytes must fit GL's 32 KB of shared memory
#endif
const int QUARTER = FFT_SIZE / 4;
layout(local_size_x = LINES, local_size_y = QUARTER) in;
#include "ocean_layout.glsl"

layout(std430, binding = 0) buffer Source { vec2 source[]; };
layout(std430, binding = 1) buffer Target { vec2 target[]; };  // may be the source buffer
layout(std430, binding = 2) readonly buffer Twiddles { vec2 twiddle[]; };  // e^{+2 pi i m / N}

uniform int u_axis;  // 0: along x (rows), 1: along z (columns)

shared vec2 workgroup_lines[LINES][2][FFT_SIZE];
int slot;  // this thread's line in the workgroup
// lines[0] and lines[1]: this thread's line, in the two buffers the stages ping-pong between.
#define lines workgroup_lines[slot]

int element(int layer, int line, int e) {
    int base = layer * FFT_SIZE * FFT_SIZE;
    return u_axis == 0 ? base + line * FFT_SIZE + e : base + e * FFT_SIZE + line;
}

vec2 times_i(vec2 a) { return vec2(-a.y, a.x); }

// One radix-4 stage of stride p, thread t's share: four inputs a quarter of the line apart, twiddled,
// give four outputs of one 4-point inverse DFT (e^{+2 pi i j q / 4}), written where the next stage reads them (Stockham).
void radix4_stage(int t, int p, int from) {
    int r = t & (p - 1);
    int step = r * (FFT_SIZE / (4 * p));  // zeta^(j r) = twiddle[j * step]
    vec2 a0 = lines[from][t];
    vec2 a1 = complex_multiply(lines[from][t + QUARTER], twiddle[step]);
    vec2 a2 = complex_multiply(lines[from][t + 2 * QUARTER], twiddle[2 * step]);
    vec2 a3 = complex_multiply(lines[from][t + 3 * QUARTER], twiddle[3 * step]);
    int out_index = (t - r) * 4 + r;
    lines[1 - from][out_index] = a0 + a1 + a2 + a3;
    lines[1 - from][out_index + p] = a0 + times_i(a1) - a2 - times_i(a3);
    lines[1 - from][out_index + 2 * p] = a0 - a1 + a2 - a3;
    lines[1 - from][out_index + 3 * p] = a0 - times_i(a1) - a2 + times_i(a3);
}

void main() {
    slot = int(gl_LocalInvocationID.x);
    int line = int(gl_WorkGroupID.x) * LINES + slot, layer = int(gl_WorkGroupID.y);  // layer = cascade * 4 + field
    int t = int(gl_LocalInvocationID.y);
    for (int j = 0; j < 4; ++j) lines[0][t + j * QUARTER] = source[element(layer, line, t + j * QUARTER)];
    barrier();

    int from = 0, p = 1;
    for (; 4 * p <= FFT_SIZE; p *= 4) {  // radix-4 stages
        radix4_stage(t, p, from);
        from = 1 - from;
        barrier();
    }
    if (p < FFT_SIZE) {  // one radix-2 stage (p = N / 2): each thread does two butterflies
        for (int half_t = t; half_t < FFT_SIZE / 2; half_t += QUARTER) {
            int r = half_t & (p - 1);
            vec2 u0 = lines[from][half_t];
            vec2 u1 = complex_multiply(lines[from][half_t + FFT_SIZE / 2], twiddle[r * (FFT_SIZE / (2 * p))]);
            int out_index = (half_t - r) * 2 + r;
            lines[1 - from][out_index] = u0 + u1;
            lines[1 - from][out_index + p] = u0 - u1;
        }
        from = 1 - from;
        barrier();
    }
    for (int j = 0; j < 4; ++j) target[element(layer, line, t + j * QUARTER)] = lines[from][t + j * QUARTER];
}
