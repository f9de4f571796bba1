#version 450 core
// Chapter 4.3, once a frame, one thread per mode: each mode turns at its own angular frequency,
//     h~(k, t) = h0(k) e^{-i omega t} + conj(h0(-k)) e^{i omega t}   (crests travel along +k),
// and the derivatives' spectra follow from it; they are written packed two real fields per
// complex one (mode.glsl says how; ocean_maps.hpp is the CPU reference). omega t is formed and
// reduced modulo 2 pi in double precision before it becomes a float, so the sea stays correct
// after days of simulated time.
layout(local_size_x = 8, local_size_y = 8) in;
#include "ocean_layout.glsl"
#include "mode.glsl"

layout(std430, binding = 0) readonly buffer InitialAmplitudes { vec2 h0[]; };  // [cascade][N*N]
layout(std430, binding = 1) readonly buffer AngularFrequencies { double omega[]; };
layout(std430, binding = 2) writeonly buffer Spectra { vec2 spectra[]; };

uniform double u_time;
uniform float u_patch_size[4];  // metres, per cascade

const double TWO_PI = 6.283185307179586476925286766559LF;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int n = u_n, i = id.x, j = id.y, cascade = id.z;
    if (i >= n || j >= n || cascade >= u_layer_count) return;
    int here = cascade * n * n + j * n + i;
    int mirror = cascade * n * n + ((n - j) % n) * n + (n - i) % n;  // -k

    float phase = float(mod(omega[here] * u_time, TWO_PI));
    vec2 h = evolve_mode(h0[here], h0[mirror], phase);
    vec2 pairs[4] = packed_pairs(h, wave_vector(ivec2(i, j), n, u_patch_size[cascade]));
    for (int f = 0; f < 4; ++f) spectra[field_base(cascade, f) + j * n + i] = pairs[f];
}
