// The four cascades' textures (step05's simulation, one layer each) and what the surface is at a
// rest position p: the sum of the cascades, each sampled at p over its own tile size.
#include "step05_fft/shaders/ocean_maps.glsl"

const int CASCADES = 4;
uniform float u_patch_sizes[CASCADES];  // metres
uniform bool u_cascade_enabled[CASCADES];
uniform sampler2DArray u_foam;          // one layer per cascade

// (l Dx, h, l Dz, l dDx/dz) summed over the cascades; lod < 0: the sampler's own (pixels).
vec4 total_displacement(vec2 p, float lod) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c) {
        if (!u_cascade_enabled[c]) continue;
        vec3 uv = vec3(p / u_patch_sizes[c], float(c));
        sum += lod < 0.0 ? texture(u_displacement, uv) : textureLod(u_displacement, uv, lod);
    }
    return sum;
}

// (dh/dx, dh/dz, l dDx/dx, l dDz/dz) summed: derivatives of a sum are sums of derivatives.
vec4 total_slopes(vec2 p) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c)
        if (u_cascade_enabled[c]) sum += texture(u_slopes, vec3(p / u_patch_sizes[c], float(c)));
    return sum;
}

float total_foam(vec2 p) {
    float sum = 0.0;
    for (int c = 0; c < CASCADES; ++c)
        if (u_cascade_enabled[c]) sum += texture(u_foam, vec3(p / u_patch_sizes[c], float(c))).r;
    // Foam reads as a white patch with an edge, not as a grey haze: sharpen the coverage.
    return smoothstep(0.05, 0.6, sum);
}
