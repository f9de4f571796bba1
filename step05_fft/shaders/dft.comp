#version 450 core
// Chapter 4.2, the notes' "transformée de fourier inverse classique": every output value is the
// whole sum over all N^2 modes, field(x) = sum_k field~(k) e^{i k.x}. O(N^4): for N <= 64 only.
// e^{i k.x} = e^{2 pi i (m x_index + m' z_index) / N} is exact through an integer phase index
// into a table of the N roots of unity.
layout(local_size_x = 64) in;
#include "ocean_layout.glsl"

layout(std430, binding = 0) readonly buffer Source { vec2 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec2 target[]; };

const int MAX_N = 64;
shared vec2 roots[MAX_N];  // e^{2 pi i q / N}

void main() {
    int n = u_n;
    int local = int(gl_LocalInvocationID.x);
    if (local < n) {
        float angle = 6.2831853071795865 * float(local) / float(n);
        roots[local] = vec2(cos(angle), sin(angle));
    }
    barrier();
    int index = int(gl_GlobalInvocationID.x);
    int layer = int(gl_GlobalInvocationID.y);  // cascade * 4 + field
    if (index >= n * n) return;
    int x = index % n, z = index / n;
    int base = layer * n * n;
    vec2 sum = vec2(0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            sum += complex_multiply(source[base + j * n + i], roots[(i * x + j * z) % n]);
    target[base + index] = sum;
}
