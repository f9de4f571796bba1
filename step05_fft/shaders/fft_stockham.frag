#version 450 core
// One radix-2 stage of the inverse FFT along one axis as a fragment pass: the FFT where there are no
// compute shaders (GL 4.1, ES 3.0, WebGL 2). The field is a float texture, one complex value a
// channel pair (two fields a texel: .rg and .ba); the host draws a full-screen triangle into the
// other texture of a pair once per stage, log2 N stages an axis.
// A compute shader scatters: each butterfly writes its two outputs. A fragment writes only its own
// texel, so each one gathers its two inputs instead. In Stockham's order (no bit reversal: each
// stage writes the order the next one reads, and the last writes the natural order) stage s, with
// M = 2^s, makes output n from
//     r = n mod M,  t = (n div 2M) M + r,  a = x[t],  b = x[t + N/2],  w = e^{+2 pi i r / (2M)}
//     y[n] = a + w b  where n mod 2M < M,   y[n] = a - w b  otherwise.
// After log2 N stages, y[n] = sum_m x[m] e^{+2 pi i m n / N}: unnormalised, like FFTW_BACKWARD.
layout(binding = 0) uniform sampler2D u_source;
uniform int u_axis;  // 0: along x (each row), 1: along y (each column)
uniform int u_span;  // M = 2^s
uniform int u_size;  // N

out vec4 o_value;

vec2 complex_multiply(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int n = u_axis == 0 ? texel.x : texel.y;  // this output's index along the axis
    int r = n % u_span;
    int t = (n / (2 * u_span)) * u_span + r;  // the thread of the scatter form that wrote output n
    ivec2 a_at = texel, b_at = texel;
    if (u_axis == 0) {
        a_at.x = t;
        b_at.x = t + u_size / 2;
    } else {
        a_at.y = t;
        b_at.y = t + u_size / 2;
    }
    vec4 a = texelFetch(u_source, a_at, 0), b = texelFetch(u_source, b_at, 0);
    float angle = 3.14159265358979 * float(r) / float(u_span);  // 2 pi r / (2M)
    vec2 w = vec2(cos(angle), sin(angle));
    float side = n % (2 * u_span) < u_span ? 1.0 : -1.0;  // a + w b, or a - w b
    o_value = vec4(a.xy + side * complex_multiply(w, b.xy), a.zw + side * complex_multiply(w, b.zw));
}
