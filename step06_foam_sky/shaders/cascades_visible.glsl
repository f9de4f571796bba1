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

uniform sampler2DArray u_slope_moments;         // (sx^2, sz^2, sx sz, 0), mipmapped (step05)
uniform float u_cascade_slope_variance[CASCADES];  // E[sx^2 + sz^2] of each whole cascade

// The slope variance this pixel's footprint averages away (LEAN mapping, Olano and Baker 2010;
// Bruneton, Neyret and Holzschuch 2010): for each cascade the mipmapped mean of s^2 less the
// square of the mipmapped mean slope, and all of the variance of the cascades the pixel cannot
// see at all. Set by total_slopes.
float unresolved_slope_variance = 0.0;

// (dh/dx, dh/dz, l dDx/dx, l dDz/dz) summed: derivatives of a sum are sums of derivatives.
vec4 total_slopes(vec2 p) {
    vec4 sum = vec4(0.0);
    unresolved_slope_variance = 0.0;
    for (int c = 0; c < CASCADES; ++c) {
        if (cascade_seen[c]) {
            vec4 slopes = texture(u_slopes, cascade_uv(p, c));
            vec2 moments = texture(u_slope_moments, cascade_uv(p, c)).xy;
            sum += slopes;
            unresolved_slope_variance += max(moments.x - slopes.x * slopes.x + moments.y - slopes.y * slopes.y, 0.0);
        } else if (u_cascade_enabled[c]) {
            unresolved_slope_variance += u_cascade_slope_variance[c];
        }
    }
    return sum;
}

float total_foam(vec2 p) {
    // Foam reads as a white patch with an edge, not as a grey haze: sharpen the coverage.
    return smoothstep(0.05, 0.6, foam_at(p));
}
