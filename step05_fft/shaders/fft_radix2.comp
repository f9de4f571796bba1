#version 450 core
// Chapter 4.4, the plain FFT (fft=radix2): one radix-2 stage of the inverse FFT along one axis, for
// every line of every field of every cascade. The host dispatches it once per stage (log2 N stages
// an axis) and ping-pongs between two buffers; README section 3 derives it.
// Stage s joins pairs of transforms of M = 2^s points into transforms of 2M points. The first
// stage reads the line in bit-reversed order, which puts the even samples' transform E beside the
// odd samples' O at every stage; each butterfly joins one frequency of one pair (fft.md, section 2).
// The result is sum_m X[m] e^{+2 pi i m n / N}, unnormalised, like FFTW_BACKWARD and fft.comp.
#ifndef FFT_SIZE
#define FFT_SIZE 256  // N
#endif
#ifndef GROUP
#define GROUP 64  // butterflies a workgroup (at most N / 2)
#endif
layout(local_size_x = GROUP) in;
#include "ocean_layout.glsl"

layout(std430, binding = 0) readonly buffer Source { vec2 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec2 target[]; };  // never the source
layout(std430, binding = 2) readonly buffer Twiddles { vec2 twiddle[]; };  // e^{+2 pi i m / N}

uniform int u_axis;   // 0: along x (rows), 1: along z (columns)
uniform int u_stage;  // s = 0 .. log2 N - 1

int element(int layer, int line, int e) {
    int base = layer * FFT_SIZE * FFT_SIZE;
    return u_axis == 0 ? base + line * FFT_SIZE + e : base + e * FFT_SIZE + line;
}

// Element e of the line as this stage sees it: the first stage reads the input bit-reversed.
vec2 line_value(int layer, int line, int e) {
    int bits = findMSB(FFT_SIZE);  // log2 N
    if (u_stage == 0) e = int(bitfieldReverse(uint(e)) >> uint(32 - bits));
    return source[element(layer, line, e)];
}

// Butterfly b of stage s: two neighbouring half-transforms E and O (M points each) joined into one.
void radix2_butterfly(int s, int b, int layer, int line) {
    int half_size = 1 << s;       // M
    int r = b & (half_size - 1);  // the frequency within the half-transforms
    int even = (b - r) * 2 + r;   // E[r] sits at base + r, base = 2M (b div M) = 2 (b - r)
    int odd = even + half_size;   // O[r] at base + M + r
    vec2 zeta_r = twiddle[r * (FFT_SIZE / (2 * half_size))];  // ζ^r = e^{2πi r/(2M)}: entry r N/(2M) of the table
    vec2 e = line_value(layer, line, even);
    vec2 o = complex_multiply(zeta_r, line_value(layer, line, odd));
    target[element(layer, line, even)] = e + o;
    target[element(layer, line, odd)] = e - o;
}

void main() {
    int b = int(gl_GlobalInvocationID.x), line = int(gl_GlobalInvocationID.y), layer = int(gl_GlobalInvocationID.z);
    radix2_butterfly(u_stage, b, layer, line);
}
