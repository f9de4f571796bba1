// From scene light to the screen, on the CPU in double precision: tonemap.frag's reference.
//
// The scene holds radiance, which has no top; a screen shows 0 to 1. tonemap.frag scales the
// light (exposure), adds the bloom, bends it through a filmic curve that rolls the highlights off
// instead of clipping them, encodes it for the screen (sRGB), and adds a dither of one 8-bit step
// so that a slow gradient (the sky) does not show bands once rounded to 8 bits.
//   - ACES, in Stephen Hill's fit of the RRT and ODT: an input matrix into the curve's space, the
//     rational curve (c (c + a) - b) / (c (d c + e) + f) on each channel, an output matrix back.
//     Each matrix's rows sum to one, so a grey stays grey.
//   - AgX (Troy Sobotka), in Benjamin Wrensch's minimal form: a matrix that pulls the colours in,
//     log2 of the light over 16.5 stops, a polynomial S-curve, a matrix back out. It returns
//     display-encoded values.
//   - sRGB: 12.92 c below 0.0031308, 1.055 c^(1/2.4) - 0.055 above (IEC 61966-2-1).
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace step06 {

enum class Tonemapper { Aces = 0, Agx = 1, None = 2 };  // tonemap.frag's TONEMAPPER

inline double linear_to_srgb(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// srgb.glsl's linear_to_srgb_fast: above 0.0031308, a quintic in q = c^(1/4) (two square roots)
// fitted to the curve, meeting the linear piece where it ends and within 1.4e-5 of the curve
// (0.0035 of an 8-bit step). The GLSL pow costs a log2 and an exp2 a channel: a sixth of
// llvmpipe's tonemap pass (docs/performance.md).
inline double linear_to_srgb_fast(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    if (c < 0.0031308) return 12.92 * c;
    const double q = std::sqrt(std::sqrt(c));
    return -0.06149789493706246 +
           q * (0.16386251512659716 +
                q * (1.2479096353224808 + q * (-0.5635971409770058 + q * (0.27758618614595343 + q * -0.06426843686354067))));
}

// GLSL's mat3 is column-major: these are the shader's constructors read column by column.
inline glm::dvec3 times_columns(const double (&m)[9], const glm::dvec3& c) {
    return {m[0] * c.x + m[3] * c.y + m[6] * c.z, m[1] * c.x + m[4] * c.y + m[7] * c.z, m[2] * c.x + m[5] * c.y + m[8] * c.z};
}

inline glm::dvec3 aces_fitted(glm::dvec3 c) {
    static constexpr double input[9] = {0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777};
    static constexpr double output[9] = {1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602};
    c = times_columns(input, c);
    for (int i = 0; i < 3; ++i) c[i] = (c[i] * (c[i] + 0.0245786) - 0.000090537) / (c[i] * (0.983729 * c[i] + 0.4329510) + 0.238081);
    c = times_columns(output, c);
    return glm::clamp(c, 0.0, 1.0);
}

inline glm::dvec3 agx(glm::dvec3 c) {
    static constexpr double inset[9] = {0.842479062253094,  0.0423282422610123, 0.0423756549057051,
                                        0.0784335999999992, 0.878468636469772,  0.0784336,
                                        0.0792237451477643, 0.0791661274605434, 0.879142973793104};
    static constexpr double outset[9] = {1.19687900512017,   -0.0528968517574562, -0.0529716355144438,
                                         -0.0980208811401368, 1.15190312990417,   -0.0980434501171241,
                                         -0.0990297440797205, -0.0989611768448433, 1.15107367264116};
    const double min_ev = -12.47393, max_ev = 4.026069;
    c = times_columns(inset, c);
    for (int i = 0; i < 3; ++i) {
        double x = std::clamp(std::log2(std::max(c[i], 1e-10)), min_ev, max_ev);
        x = (x - min_ev) / (max_ev - min_ev);
        const double x2 = x * x, x4 = x2 * x2;
        c[i] = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
    }
    return glm::clamp(times_columns(outset, c), 0.0, 1.0);
}

// Jimenez's interleaved gradient noise, a value in [0, 1) at the pixel centre `fragment`
// (gl_FragCoord).
inline double interleaved_gradient_noise(glm::dvec2 fragment) {
    const double inner = fragment.x * 0.06711056 + fragment.y * 0.00583715;
    const double outer = 52.9829189 * (inner - std::floor(inner));
    return outer - std::floor(outer);
}

// The dither's offset at a pixel, in [-1, 1] of an 8-bit step and triangular: r uniform in
// [-1, 1], sign(r) (1 - sqrt(1 - |r|)) has the density 1 - |x|.
inline double dither_offset(glm::dvec2 fragment) {
    const double r = 2.0 * interleaved_gradient_noise(fragment) - 1.0;
    return std::copysign(1.0 - std::sqrt(1.0 - std::abs(r)), r) / 255.0;
}

// tonemap.frag at one pixel: the value it writes before the target rounds it to 8 bits.
inline glm::dvec3 tonemap(const glm::dvec3& scene, const glm::dvec3& bloom, double exposure, double bloom_strength,
                          Tonemapper curve, glm::dvec2 fragment) {
    const glm::dvec3 c = (scene + bloom_strength * bloom) * exposure;
    glm::dvec3 encoded;
    if (curve == Tonemapper::Agx) {
        encoded = agx(c);
    } else {
        const glm::dvec3 display = curve == Tonemapper::Aces ? aces_fitted(c) : c;
        for (int i = 0; i < 3; ++i) encoded[i] = linear_to_srgb_fast(display[i]);
    }
    return encoded + dither_offset(fragment);
}

}  // namespace step06
