#version 450 core
// One radix-2 stage of the inverse FFT along one axis as a fragment pass: the FFT where there are no
// compute shaders (GL 4.1, ES 3.0, WebGL 2). The field is a float texture, one complex value a
// channel pair (two fields a texel: .rg and .ba); the host draws a full-screen triangle into the
// other texture of a pair once per stage, log2 N stages an axis.
// A compute shader scatters: each butterfly writes its two outputs. A fragment writes only its own
// texel, so each one gathers its two inputs instead. In Stockham's order (no bit reversal: each
// stage writes the order the next one reads, and the last writes the natural order) stage s, with
// M = 2^s, makes output i from
//     k = i mod M,  j = (i div 2M) M + k,  a = x[j],  b = x[j + N/2],  w = e^{+2 pi i k / (2M)}
//     y[i] = a + w b  where i mod 2M < M,   y[i] = a - w b  otherwise.
// After log2 N stages, y[n] = sum_m x[m] e^{+2 pi i m n / N}: unnormalised, like FFTW_BACKWARD.
layout(binding = 0) uniform sampler2D u_source;
uniform int u_axis;  // 0: along x (each row), 1: along y (each column)
uniform int u_span;  // M = 2^s
uniform int u_size;  // N

out vec4 o_value;

vec2 complex_multiply(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int i = u_axis == 0 ? texel.x : texel.y;
    int k = i % u_span;
    int j = (i / (2 * u_span)) * u_span + k;
    ivec2 a_at = texel, b_at = texel;
    if (u_axis == 0) {
        a_at.x = j;
        b_at.x = j + u_size / 2;
    } else {
        a_at.y = j;
        b_at.y = j + u_size / 2;
    }
    vec4 a = texelFetch(u_source, a_at, 0), b = texelFetch(u_source, b_at, 0);
    float angle = 3.14159265358979 * float(k) / float(u_span);  // 2 pi k / (2M)
    vec2 w = vec2(cos(angle), sin(angle));
    float side = i % (2 * u_span) < u_span ? 1.0 : -1.0;  // a + w b, or a - w b
    o_value = vec4(a.xy + side * complex_multiply(w, b.xy), a.zw + side * complex_multiply(w, b.zw));
}
