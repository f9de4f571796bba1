// Chapter 3 on the GPU (fbm.hpp is the CPU reference): cascades of fBm waves, each wave a sine,
// exp(sin - 1) or ((1 + sin) / 2)^3, with domain warping and the exact gradient of the warped sum.
#ifndef SHAPE
#define SHAPE 1  // 0: sin, 1: exp(sin - 1), 2: ((1 + sin) / 2)^3. A compile-time choice, like step03's variants.
#endif

const int MAX_CASCADES = 4;
const int MAX_WAVES_PER_CASCADE = 64;

struct FbmWave {
    vec4 direction_wavenumber_amplitude;  // (d.x, d.z, w, a)
    vec4 phase;                           // (-t phi mod 2 pi, 0, 0, 0), reduced on the CPU in double
};

// Cascade c's waves are u_fbm_waves[c * MAX_WAVES_PER_CASCADE + i]. A uniform block, because
// 4 x 64 waves would not fit in plain uniforms.
layout(std140, binding = 0) uniform FbmWaves {
    FbmWave u_fbm_waves[MAX_CASCADES * MAX_WAVES_PER_CASCADE];
};
uniform int u_cascade_count;
uniform int u_waves_per_cascade;
uniform float u_warp;  // beta: the point moves by beta a grad f of each wave before (dimensionless)

// (W, W', W'') of GPU Gems 1's sharpened sine, ((1 + sin theta) / 2)^3, scaled to the exp-sine's
// crest-to-trough height 1 - e^-2 and less its mean over a period (fbm.hpp's power_sine_shape is
// the CPU reference).
vec3 power_sine_shape(float theta) {
    float s = sin(theta), c = cos(theta), u = 0.5 * (1.0 + s);
    const float SCALE = 0.86466472;  // 1 - e^-2
    return SCALE * vec3(u * u * u - 0.3125, 1.5 * u * u * c, 1.5 * (u * c * c - u * u * s));
}

// (W, W', W'') at theta.
vec3 wave_shape(float theta) {
    float s = sin(theta), c = cos(theta);
#if SHAPE == 0
    const float SINE_SCALE = 0.43233236;  // (1 - e^-2) / 2: the exp-sine's crest-to-trough height
    return SINE_SCALE * vec3(s, c, -s);
#elif SHAPE == 2
    return power_sine_shape(theta);
#else
    float e = exp(s - 1.0);
    const float MEAN = 0.46575961;  // e^-1 I0(1): subtracted so the sea's mean level is y = 0
    return vec3(e - MEAN, e * c, e * (c * c - s));
#endif
}

// The chain rule through the warp, for one wave (fbm.hpp's cascade_height_gradient is the CPU
// reference): the wave (d, w, a) is read at the warped point q, where shape = (W, W', W'') and its
// gradient is slope. Adds the wave's gradient with respect to the rest position p to total.yz, and
// keeps jacobian = dq/dp up to date past this wave's push, q -= u_warp a slope (the caller's next
// line). README "The normal stays exact" derives both.
void warp_chain_rule(vec2 d, float w, float a, vec3 shape, vec2 slope, inout vec3 total, inout mat2 jacobian) {
    total.yz += transpose(jacobian) * slope;
    jacobian = (mat2(1.0) - u_warp * a * a * w * w * shape.z * outerProduct(d, d)) * jacobian;
}

// (h, dh/dx, dh/dz) at rest position p.
vec3 fbm_height_gradient(vec2 p) {
    vec3 total = vec3(0.0);
    for (int c = 0; c < u_cascade_count; ++c) {
        vec2 q = p;              // the warped point
        mat2 jacobian = mat2(1.0);  // dq/dp
        for (int i = 0; i < u_waves_per_cascade; ++i) {
            FbmWave wave = u_fbm_waves[c * MAX_WAVES_PER_CASCADE + i];
            vec2 d = wave.direction_wavenumber_amplitude.xy;
            float w = wave.direction_wavenumber_amplitude.z;
            float a = wave.direction_wavenumber_amplitude.w;
            vec3 shape = wave_shape(dot(d, q) * w + wave.phase.x);
            vec2 slope = a * w * shape.y * d;  // gradient of this wave at q
            total.x += a * shape.x;
            warp_chain_rule(d, w, a, shape, slope, total, jacobian);
            q -= u_warp * a * slope;
        }
    }
    return total;
}

// The unit normal from the gradient: the surface's two tangents crossed, in the order that points
// out of the water, as step03 builds it (step03's README, "Tangent, bitangent, normal").
vec3 fbm_normal(vec2 gradient) {
    return normalize(vec3(-gradient.x, 1.0, -gradient.y));
}
