#version 450 core
// From scene light to screen: exposure, bloom added, a filmic curve (ACES fitted, or AgX), sRGB
// encoding and a dither (tonemap.hpp holds all of it on the CPU in double, for the tests).
#include "srgb.glsl"

#ifndef TONEMAPPER
#define TONEMAPPER 0  // 0: ACES (Hill's fit), 1: AgX (minimal), 2: none (clamp)
#endif
#ifndef DITHER
#define DITHER 1  // 0: no dither (tonemapper none: the debug views, and pictures made to be measured)
#endif

in vec2 v_uv;
out vec4 out_colour;

uniform sampler2D u_scene;
uniform sampler2D u_bloom;
uniform float u_exposure;
uniform float u_bloom_strength;

vec3 aces_fitted(vec3 c) {
    const mat3 input_matrix = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 output_matrix = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    c = input_matrix * c;
    c = (c * (c + 0.0245786) - 0.000090537) / (c * (0.983729 * c + 0.4329510) + 0.238081);
    return clamp(output_matrix * c, 0.0, 1.0);
}

// AgX (Troy Sobotka), in the minimal form by Benjamin Wrensch: returns display-encoded values.
vec3 agx(vec3 c) {
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051, 0.0784335999999992,
                            0.878468636469772, 0.0784336, 0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438, -0.0980208811401368,
                             1.15190312990417, -0.0980434501171241, -0.0990297440797205, -0.0989611768448433,
                             1.15107367264116);
    const float min_ev = -12.47393, max_ev = 4.026069;
    c = clamp(log2(max(inset * c, vec3(1e-10))), min_ev, max_ev);
    c = (c - min_ev) / (max_ev - min_ev);
    vec3 c2 = c * c, c4 = c2 * c2;
    c = 15.5 * c4 * c2 - 40.14 * c4 * c + 31.96 * c4 - 6.868 * c2 * c + 0.4298 * c2 + 0.1191 * c - 0.00232;
    return clamp(outset * c, 0.0, 1.0);
}

// A dither of one 8-bit step, triangular (TPDF): added before the target rounds to 8 bits, it
// keeps a slow gradient's mean on the true value between two steps, so the sky shows no bands,
// and the error's variance (1/4 step^2) does not depend on the colour. One uniform value from
// Jimenez's interleaved gradient noise at this pixel, r in [-1, 1], made triangular by
// sign(r) (1 - sqrt(1 - |r|)) (Gjol, "Banding in Games", 2016). Until issue 23's eleventh stop this
// was the noise minus the same noise 7 and 13 pixels away, which is not a second independent
// value: that noise is nearly a linear ramp, so the difference took two values, -0.91 and +0.09 of
// a step, and the bands stayed (tonemap.hpp's test measures both). Deterministic: the same pixel
// gets the same offset every frame.
float interleaved_gradient_noise(vec2 fragment) {
    return fract(52.9829189 * fract(dot(fragment, vec2(0.06711056, 0.00583715))));
}

vec3 dither(vec3 srgb) {
    float r = 2.0 * interleaved_gradient_noise(gl_FragCoord.xy) - 1.0;
    return srgb + sign(r) * (1.0 - sqrt(1.0 - abs(r))) / 255.0;
}

void main() {
    // The scene is this pixel's own texel (the target has the screen's size): texelFetch skips the
    // filtering that texture() would spend on it (1 ms of llvmpipe's 8). The bloom, a quarter of the
    // screen, is magnified bilinearly.
    vec3 c = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb + u_bloom_strength * texture(u_bloom, v_uv).rgb;
    c *= u_exposure;
#if TONEMAPPER == 0
    vec3 srgb = linear_to_srgb_fast(aces_fitted(c));
#elif TONEMAPPER == 1
    vec3 srgb = agx(c);
#else
    vec3 srgb = linear_to_srgb_fast(c);
#endif
#if DITHER
    out_colour = vec4(dither(srgb), 1.0);
#else
    out_colour = vec4(srgb, 1.0);
#endif
}
