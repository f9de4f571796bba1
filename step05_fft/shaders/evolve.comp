#version 450 core
// Chapter 4.3, once a frame: each mode turns at its own angular frequency,
//     h~(k, t) = h0(k) e^{-i omega t} + conj(h0(-k)) e^{i omega t}   (crests travel along +k),
// and the derivatives' spectra follow from it; they are written packed two real fields per
// complex one (see ocean_maps.hpp). omega t is formed and reduced modulo 2 pi in double precision
// before it becomes a float, so the sea stays correct after days of simulated time.
layout(local_size_x = 8, local_size_y = 8) in;
#include "ocean_layout.glsl"

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
    vec2 rotation = vec2(cos(phase), -sin(phase));  // e^{-i omega t}
    vec2 h0_minus = h0[mirror];
    vec2 h = complex_multiply(h0[here], rotation) +
             complex_multiply(vec2(h0_minus.x, -h0_minus.y), vec2(rotation.x, -rotation.y));

    float dk = 6.2831853 / u_patch_size[cascade];
    vec2 k = dk * vec2(i < n / 2 ? i : i - n, j < n / 2 ? j : j - n);
    float length_k = length(k);
    vec2 pairs[4] = vec2[4](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    if (length_k > 0.0) {
        vec2 i_h = vec2(-h.y, h.x);            // i h~
        vec2 dx = i_h * (k.x / length_k);      // +i kx/|k| h~: points crowd to the crests
        vec2 dz = i_h * (k.y / length_k);
        vec2 sx = i_h * k.x, sz = i_h * k.y;   // i k h~
        vec2 dxx = -h * (k.x * k.x / length_k), dzz = -h * (k.y * k.y / length_k);  // i kx (i kx/|k| h~)
        vec2 dxz = -h * (k.x * k.y / length_k);
        // a + i b for each pair (real field a, real field b)
        pairs[0] = h + vec2(-dx.y, dx.x);
        pairs[1] = dz + vec2(-sx.y, sx.x);
        pairs[2] = sz + vec2(-dxx.y, dxx.x);
        pairs[3] = dzz + vec2(-dxz.y, dxz.x);
    }
    for (int f = 0; f < 4; ++f) spectra[field_base(cascade, f) + j * n + i] = pairs[f];
}
