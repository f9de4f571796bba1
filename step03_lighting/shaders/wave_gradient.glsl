// Chapter 2: the height and its two partial derivatives in one loop over the waves
// (normals.hpp is the CPU reference). The sum itself is step02's.
#include "step02_sine3d/shaders/waves.glsl"

// (h, dh/dx, dh/dz): the height and its two partial derivatives in the same pass over the waves,
// each wave differentiated by the chain rule (README, "Derivatives in the same loop").
vec3 wave_height_gradient(vec2 xz) {
    vec3 result = vec3(0.0);
    for (int i = 0; i < u_wave_count; ++i) {
        vec4 wave = u_waves[i];  // (d.x, d.z, w, a)
        float angle = dot(wave.xy, xz) * wave.z + u_wave_phases[i];
        result.x += wave.w * sin(angle);
        result.yz += wave.z * wave.w * cos(angle) * wave.xy;
    }
    return result;
}

// The notes' slope: central differences of the height, step s metres along each axis.
vec3 finite_difference_gradient(vec2 xz, float s) {
    vec2 dx = vec2(s, 0.0), dz = vec2(0.0, s);
    return vec3(wave_height(xz),
                (wave_height(xz + dx) - wave_height(xz - dx)) / (2.0 * s),
                (wave_height(xz + dz) - wave_height(xz - dz)) / (2.0 * s));
}

// N = normalize(B x T) with T = (1, dh/dx, 0) and B = (0, dh/dz, 1).
vec3 surface_normal(vec2 gradient) {
    return normalize(vec3(-gradient.x, 1.0, -gradient.y));
}
