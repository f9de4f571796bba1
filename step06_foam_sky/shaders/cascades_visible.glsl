// For fragment shaders (they use screen-space derivatives): the cascades summed as this pixel
// sees them, filtered over the pixel's footprint on the sea.
#include "cascades.glsl"
#include "foam_map.glsl"

#ifndef ANISOTROPIC_TAPS
#define ANISOTROPIC_TAPS 2  // most samples along a pixel's long footprint (1: isotropic trilinear)
#endif

uniform sampler2DArray u_slope_moments;         // (sx^2, sz^2, sx sz, 0), mipmapped (step05)
uniform float u_cascade_slope_variance[CASCADES];  // E[sx^2 + sz^2] of each whole cascade

// What the pixel sees of the summed surface: set by sample_surface.
struct SurfaceSample {
    vec4 displacement;  // (l Dx, h, l Dz, l dDx/dz)
    vec4 slopes;        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz): derivatives of a sum are sums
    // The slope variance the footprint averages away (LEAN mapping, Olano and Baker 2010;
    // Bruneton, Neyret and Holzschuch 2010): for each cascade the filtered mean of s^2 less the
    // square of the filtered mean slope, and all of the variance of the cascades the pixel cannot
    // see at all. It becomes microfacet roughness.
    float unresolved_slope_variance;
};

// A pixel looking at the sea at a grazing angle covers a long, thin ellipse of it: metres deep
// along the view, centimetres across. A trilinear fetch has one width: GL takes the long axis
// (the mip level that averages the whole length), which also blurs away every wave across the
// view and leaves horizontal smears, the "combed" look. So the long axis is cut into up to
// ANISOTROPIC_TAPS pieces, each fetched at the mip level of its own width, and the pieces are
// averaged: what hardware anisotropic filtering does, written out because llvmpipe's is 25x
// slower, and because the moments must be averaged over exactly the same samples as the slopes
// (E[s^2] - E[s]^2 is only a variance if both means are over one footprint).
SurfaceSample sample_surface(vec2 p) {
    vec2 dx = dFdx(p), dy = dFdy(p);
    float lx = length(dx), ly = length(dy);
    vec2 long_axis = lx > ly ? dx : dy;
    float long_length = max(lx, ly), short_length = min(lx, ly);
    // Each tap averages long / taps, but never less than the short axis.
    float texels = float(textureSize(u_slopes, 0).x);

    SurfaceSample s;
    s.displacement = vec4(0.0);
    s.slopes = vec4(0.0);
    s.unresolved_slope_variance = 0.0;
    for (int c = 0; c < CASCADES; ++c) {
        if (!u_cascade_enabled[c]) continue;
        // Pieces no shorter than the short axis, nor than a texel (below a texel the map is
        // magnified: one fetch is exact), so a long tile near the camera takes one fetch.
        float texel = u_patch_sizes[c] / texels;
        int taps = clamp(int(ceil(long_length / max(short_length, texel) - 0.01)), 1, ANISOTROPIC_TAPS);
        float footprint = max(short_length, long_length / float(taps));  // metres each tap averages
        // Where one tap covers more than half a cascade's tile, the cascade's mipmaps have averaged
        // it to its mean, which is zero (a periodic tile has no mean slope or displacement):
        // skipping it changes nothing but its variance, and saves its fetches (the small cascades,
        // over most of the distant sea).
        if (footprint >= 0.5 * u_patch_sizes[c]) {
            s.unresolved_slope_variance += u_cascade_slope_variance[c];
            continue;
        }
        // The slopes, which make the highlights, piece by piece: textureGrad with the pixel's own
        // derivatives, the long one shortened to a piece (GL picks the level from the longer of
        // the two: the piece's width). The displacement (it moves the normal only through its
        // choppy term) and the second moments (a variance is a smooth statistic of the
        // footprint) once each, over the whole footprint.
        float to_uv = 1.0 / u_patch_sizes[c];
        vec2 grad_x = dx * to_uv, grad_y = dy * to_uv;
        if (lx > ly) grad_x /= float(taps); else grad_y /= float(taps);
        vec4 slopes = vec4(0.0);
        for (int i = 0; i < taps; ++i)
            slopes += textureGrad(u_slopes, cascade_uv(p + long_axis * ((float(i) + 0.5) / float(taps) - 0.5), c),
                                  grad_x, grad_y);
        slopes /= float(taps);
        vec3 uv = cascade_uv(p, c);
        vec2 moments = textureGrad(u_slope_moments, uv, dx * to_uv, dy * to_uv).xy;
        s.displacement += textureGrad(u_displacement, uv, dx * to_uv, dy * to_uv);
        s.slopes += slopes;
        s.unresolved_slope_variance +=
            max(moments.x - slopes.x * slopes.x + moments.y - slopes.y * slopes.y, 0.0);
    }
    return s;
}

// Foam at rest position p (fragment shaders): the finest level that holds p, blended into the
// next one over the outer tenth of its window, none beyond the largest window. From the finest
// level out, a level is read only if p is in it and the finer ones left it some weight: most of the
// sea needs one fetch, the distant sea none.
float foam_at(vec2 p) {
    // Derivatives in uniform control flow; the fetches below are in branches, so they take them
    // explicitly (textureGrad).
    vec2 dp_dx = dFdx(p), dp_dy = dFdy(p);
    float foam = 0.0, left = 1.0;  // left: the weight the finer levels did not take
    for (int level = 0; level < FOAM_LEVELS && left > 0.0; ++level) {
        vec2 offset = abs(p - u_foam_centre[level]);
        float inside = 0.5 * u_foam_extent[level] - max(offset.x, offset.y);  // metres from the edge
        float weight = clamp(inside / (0.1 * u_foam_extent[level]), 0.0, 1.0);
        if (weight <= 0.0) continue;
        float to_uv = 1.0 / u_foam_extent[level];
        foam += left * weight * textureGrad(u_foam, vec3(p * to_uv, float(level)), dp_dx * to_uv, dp_dy * to_uv).r;
        left *= 1.0 - weight;
    }
    return foam;
}

uniform sampler2D u_foam_pattern;   // foam_pattern.hpp: 1 on the borders of bubble cells
uniform float u_foam_pattern_size;  // metres one tile of it covers

// foam_pattern.hpp's foam_cover: fresh foam (amount 1) covers everything; as it decays the cell
// middles open first and the borders last, so a fading whitecap turns to lace, with a soft edge.
const float FOAM_HOLES = 0.5, FOAM_EDGE = 0.3;
float foam_cover(float amount, float pattern) {
    return smoothstep(0.0, 1.0, (amount - (1.0 - pattern) * FOAM_HOLES) / FOAM_EDGE);
}

// The simulated amount laid out by the pattern, read at two scales (so the cells are not all one
// size and the tile does not show) in world space, where the foam is.
float total_foam(vec2 p) {
    vec2 uv = p / u_foam_pattern_size;
    float pattern = 0.6 * texture(u_foam_pattern, uv).r + 0.4 * texture(u_foam_pattern, uv * 2.71 + 0.37).r;
    return foam_cover(foam_at(p), pattern);
}
