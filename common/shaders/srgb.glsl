// Lighting adds light linearly; screens expect sRGB-encoded values. Encode last, once.
vec3 linear_to_srgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

// The same curve for a pass where every pixel pays for it (step06's tonemap): above 0.0031308 a
// quintic in q = c^(1/4), fitted to 1.055 c^(1/2.4) - 0.055, meeting the linear piece where it
// ends and within 1.4e-5 of the curve (0.0035 of an 8-bit step): two square roots where pow takes
// a log2 and an exp2 a channel. On llvmpipe that is a sixth of the tonemap pass.
// step06_foam_sky/tonemap.hpp holds it in double.
vec3 linear_to_srgb_fast(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    vec3 q = sqrt(sqrt(c));
    vec3 curve = -0.06149789493706246 +
                 q * (0.16386251512659716 +
                      q * (1.2479096353224808 + q * (-0.5635971409770058 + q * (0.27758618614595343 + q * -0.06426843686354067))));
    return mix(12.92 * c, curve, step(0.0031308, c));
}
