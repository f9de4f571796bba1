// One Gerstner wave in closed form (README section 4; GPU Gems 1, chapter 1), in the form of the
// FFT's maps so that `--set sea=gerstner` can draw it in their place, with theta = k d.p - phase:
// the height, the horizontal displacement along d that sharpens the crests, and their derivatives.
// The CPU reference is step05_fft/gerstner.hpp.
struct MapSample {
    vec4 displacement;  // (Q Dx, h, Q Dz, Q dDx/dz)
    vec4 slopes;        // (dh/dx, dh/dz, Q dDx/dx, Q dDz/dz)
};

// wave = (d.x, d.z, k, A), d a unit vector; steepness Q; phase = omega t, reduced in double on the CPU.
MapSample gerstner_wave(vec2 p, vec4 wave, float steepness, float phase) {
    vec2 d = wave.xy;
    float k = wave.z, a = wave.w, q = steepness;
    float theta = k * dot(d, p) - phase;
    float c = cos(theta), s = sin(theta);
    MapSample m;
    m.displacement = vec4(-q * a * d.x * s, a * c, -q * a * d.y * s, -q * a * k * d.x * d.y * c);
    m.slopes = vec4(-a * k * d * s, -q * a * k * d.x * d.x * c, -q * a * k * d.y * d.y * c);
    return m;
}
