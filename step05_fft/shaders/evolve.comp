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
    // The four packed pairs a + i b (real field a, real field b), with u = k/|k|:
    //     h + i Dx         = h + i (i ux h)              = (1 - ux) h
    //     Dz + i dh/dx     = i uz h + i (i kx h)         = -kx h + uz (i h)
    //     dh/dz + i dDx/dx = i kz h + i (i kx)(i ux h)   = (kz - kx ux) (i h)
    //     dDz/dz + i dDx/dz = i kz (i uz h) + i (i kz)(i ux h) = -uz (kz h + kx (i h))
    // written as real multiples of h and i h. Not for speed: NVIDIA's driver (580, H100) compiled
    // the nested i (i ...) swizzles of the straightforward version with x and y exchanged, and
    // FftTest.EvolvedSpectraMatchTheFormulas caught it there (llvmpipe was right).
    vec2 pairs[4] = vec2[4](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    if (length_k > 0.0) {
        vec2 u = k / length_k;
        vec2 i_h = vec2(-h.y, h.x);
        pairs[0] = (1.0 - u.x) * h;
        pairs[1] = -k.x * h + u.y * i_h;
        pairs[2] = (k.y - k.x * u.x) * i_h;
        pairs[3] = -u.y * (k.y * h + k.x * i_h);
    }
    for (int f = 0; f < 4; ++f) spectra[field_base(cascade, f) + j * n + i] = pairs[f];
}
