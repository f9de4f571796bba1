// Chapter 4.3 and 4.5 for one mode of the spectrum: where it sits, how it turns with time, and the
// maps it gives. evolve.comp runs them at every texel; ocean_maps.cpp is the CPU reference.
// Needs complex_multiply (ocean_layout.glsl), included before this file.

// The wave vector k = 2 pi (n, m) / L that texel (i, j) of an N x N spectrum holds, in the order
// the FFT keeps its frequencies (README, "A math primer").
vec2 wave_vector(ivec2 texel, int n, float patch_size) {
    ivec2 signed_index = ivec2(texel.x < n / 2 ? texel.x : texel.x - n, texel.y < n / 2 ? texel.y : texel.y - n);
    return (6.2831853 / patch_size) * vec2(signed_index);
}

// The mode at time t from h0(k) and h0(-k), given phase = omega t reduced to [0, 2 pi): the
// crests of h0(k) travel along +k, and the spectrum stays Hermitian, so the height comes out real
// (README section 2).
vec2 evolve_mode(vec2 h0_k, vec2 h0_minus_k, float phase) {
    vec2 rotation = vec2(cos(phase), -sin(phase));  // e^{-i omega t}
    return complex_multiply(h0_k, rotation) +
           complex_multiply(vec2(h0_minus_k.x, -h0_minus_k.y), vec2(rotation.x, -rotation.y));
}

// The eight maps' spectra from h~, packed two real fields a + i b per complex transform (README
// section 4, "Two real maps per transform"): h + i Dx, Dz + i dh/dx, dh/dz + i dDx/dx and
// dDz/dz + i dDx/dz, each written as real multiples of h and i h. Not for speed: NVIDIA's driver
// (580, H100) compiled the nested i (i ...) swizzles of the straightforward version with x and y
// exchanged, and FftTest.EvolvedSpectraMatchTheFormulas caught it there (llvmpipe was right).
// k = 0 (the mean level) gives nothing.
vec2[4] packed_pairs(vec2 h, vec2 k) {
    vec2 pairs[4] = vec2[4](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    float length_k = length(k);
    if (length_k > 0.0) {
        vec2 u = k / length_k;
        vec2 i_h = vec2(-h.y, h.x);
        pairs[0] = (1.0 - u.x) * h;
        pairs[1] = -k.x * h + u.y * i_h;
        pairs[2] = (k.y - k.x * u.x) * i_h;
        pairs[3] = -u.y * (k.y * h + k.x * i_h);
    }
    return pairs;
}
