// Lighting adds light linearly; screens expect sRGB-encoded values. Encode last, once.
vec3 linear_to_srgb(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
