// For fragment shaders (they use screen-space derivatives): the cascades summed over only the
// ones a pixel can resolve.
#include "cascades.glsl"
#include "foam_map.glsl"

// Fragment shaders only: which cascades this pixel can see. Where one pixel covers more than half
// a cascade's tile, the cascade's mipmaps have averaged it to its mean, which is zero (a periodic
// tile has no mean slope or displacement): skipping it changes nothing and saves its fetches
// (the small cascades, over most of the distant sea).
bool cascade_seen[CASCADES];
void find_visible_cascades(vec2 p) {
    float footprint = max(length(dFdx(p)), length(dFdy(p)));  // metres per pixel
    for (int c = 0; c < CASCADES; ++c) cascade_seen[c] = u_cascade_enabled[c] && footprint < 0.5 * u_patch_sizes[c];
}

// (l Dx, h, l Dz, l dDx/dz) summed over the cascades this pixel sees.
vec4 visible_displacement(vec2 p) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c)
        if (cascade_seen[c]) sum += texture(u_displacement, cascade_uv(p, c));
    return sum;
}

// (dh/dx, dh/dz, l dDx/dx, l dDz/dz) summed: derivatives of a sum are sums of derivatives.
vec4 total_slopes(vec2 p) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c)
        if (cascade_seen[c]) sum += texture(u_slopes, cascade_uv(p, c));
    return sum;
}

float total_foam(vec2 p) {
    // Foam reads as a white patch with an edge, not as a grey haze: sharpen the coverage.
    return smoothstep(0.05, 0.6, foam_at(p));
}
