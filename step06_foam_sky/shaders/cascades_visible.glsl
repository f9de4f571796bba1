// For the shading pass (ocean_shade.glsl): the cascades summed as this pixel sees them, filtered
// over the pixel's footprint on the sea. The footprint is given (the deferred shading pass reads
// it from the G-buffer, gbuffer.hpp): GL's own level for texture()
// comes from the differences across a 2 x 2 quad, meaningless where the quad straddles a crest
// and the water behind it, so every fetch here takes the bias that turns GL's level into the one
// the footprint asks for.
#ifdef OCEAN_GL_PORTABLE
// No votes between neighbouring pixels in GL 4.1 or ES 3.0 (ARB_shader_group_vote is GL 4.6's):
// every fetch takes its level from the pixel's own footprint (textureLod), so a pixel may take
// its own loop length, or skip a cascade, whatever its neighbours do.
#ifndef EXPLICIT_LEVELS
#define EXPLICIT_LEVELS 1
#endif
#else
#extension GL_ARB_shader_group_vote : enable  // sample_surface: one loop length for neighbours (below)
#ifdef GL_ARB_shader_group_vote
#define GROUP_VOTES 1
#endif
#endif
#include "cascades.glsl"
#include "foam_map.glsl"

#ifndef ANISOTROPIC_TAPS
#define ANISOTROPIC_TAPS 4  // most samples along a pixel's long footprint (1: isotropic trilinear)
#endif

// The slope variance each mip level of each cascade averages away, from the spectrum
// (step05's unresolved_slope_variance_by_level; MIP_LEVELS a cascade, the last ones repeating
// the whole cascade's variance).
const int MIP_LEVELS = 10;
uniform float u_unresolved_slope_variance[CASCADES * MIP_LEVELS];

float unresolved_at(int c, float lod) {
    float level = clamp(lod, 0.0, float(MIP_LEVELS - 1));
    int below = int(floor(level)), above = min(below + 1, MIP_LEVELS - 1);
    return mix(u_unresolved_slope_variance[c * MIP_LEVELS + below], u_unresolved_slope_variance[c * MIP_LEVELS + above],
               level - float(below));
}

// A pixel's footprint on the sea: the screen derivatives of the rest position (metres per pixel).
struct SurfaceFootprint {
    vec2 dx, dy;
};

#ifndef EXPLICIT_LEVELS
// The longer side of the footprint GL assumes for texture(): from the quad's differences of p.
float implicit_long_side(vec2 p) { return max(max(length(dFdxCoarse(p)), length(dFdyCoarse(p))), 1e-20); }
#endif

// What the pixel sees of the summed surface: set by sample_surface. Not the displacement: the
// mesh has moved the point, and the normal's cross term l dDx/dz comes from its vertices too.
struct SurfaceSample {
    vec4 slopes;        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz): derivatives of a sum are sums
    // The slope variance the footprint averages away (Bruneton, Neyret and Holzschuch 2010): for
    // each cascade what the mip level of the pixel's footprint leaves out, and all of the variance
    // of the cascades the pixel cannot see at all. It becomes microfacet roughness.
    float unresolved_slope_variance;
};

// A pixel looking at the sea at a grazing angle covers a long, thin ellipse of it: metres deep
// along the view, centimetres across. A trilinear fetch has one width: GL takes the long axis
// (the mip level that averages the whole length), which also blurs away every wave across the
// view and leaves horizontal smears, the "combed" look. So the long axis is cut into up to
// ANISOTROPIC_TAPS pieces, each fetched at the mip level of its own width, and the pieces are
// averaged: what hardware anisotropic filtering does, written out because llvmpipe's is 26x
// slower.
// One cascade's part of sample_surface, added to s: its slopes over the pixel's footprint (the
// long axis cut into pieces) and the slope variance the footprint averages away.
void add_cascade(int c, vec2 p, vec2 long_axis, float long_length, float short_length, inout SurfaceSample s) {
    if (!u_cascade_enabled[c]) return;
    float texels = float(textureSize(u_slopes, 0).x);
    // Pieces no shorter than the short axis, nor than a texel (below a texel the map is
    // magnified: one fetch is exact), so a long tile near the camera takes one fetch.
    float texel = u_patch_sizes[c] / texels;
    // Rounded, not ceiled: a footprint less than 1.5 times longer than wide takes one fetch
    // (slightly over-blurred), which spares most of the near sea a second one.
    int taps = clamp(int(long_length / max(short_length, texel) + 0.5), 1, ANISOTROPIC_TAPS);
#ifdef GROUP_VOTES
    // Neighbouring pixels run in lockstep (a GPU's warp, llvmpipe's 8-wide vectors): a loop
    // whose length differs between them runs as long as the longest, its other pixels masked
    // off, and the masking itself costs (llvmpipe: 95 ms for the pass against 83). So the
    // group agrees on its longest: a pixel given more pieces than it needs cuts its footprint
    // finer, which filters it no worse.
    int wanted = taps;
    taps = 1;
    for (int more = 2; more <= ANISOTROPIC_TAPS; ++more)
        if (anyInvocationARB(wanted >= more)) taps = more;
#endif
    float footprint = max(short_length, long_length / float(taps));  // metres each tap averages
    // Where one tap covers more than half a cascade's tile, the cascade's mipmaps have averaged
    // it to its mean, which is zero (a periodic tile has no mean slope or displacement):
    // skipping it changes nothing but its variance, and saves its fetches (the small cascades,
    // over most of the distant sea).
    bool averaged_away = footprint >= 0.5 * u_patch_sizes[c];
#ifdef GROUP_VOTES
    // Skipped only where the whole group agrees: the texture() calls below take their level
    // from the 2 x 2 quad, which must all run them. A quad straddling two triangles of the
    // mesh (thin ones near the horizon) has two footprints; where only some of its pixels
    // skipped, NVIDIA's driver gave the others undefined levels: dark dashes along the
    // horizon (llvmpipe runs the whole quad anyway). A pixel that reads a cascade it could
    // skip reads its mean, about zero, and the variance below is the whole cascade's.
    averaged_away = allInvocationsARB(averaged_away);
#endif
    if (averaged_away) {
        s.unresolved_slope_variance += u_unresolved_slope_variance[c * MIP_LEVELS + MIP_LEVELS - 1];
        return;
    }
    // The slopes, which make the highlights, piece by piece: texture() with GL's own level
    // moved by a bias to the piece's width. texture(), not
    // textureGrad: llvmpipe picks one level per 2 x 2 pixels for implicit derivatives and one
    // per pixel for explicit ones, which made the pass 30 % slower. Everything that decides
    // the loop comes from the recorded coarse (per 2 x 2) derivatives, so the 2 x 2 pixels
    // agree on it.
#ifdef EXPLICIT_LEVELS
    // A pass with no 2 x 2 quads (lab/compute_shading), or no votes (the portable profile): each
    // piece at its own footprint's level.
    float lod = cascade_lod(c, footprint);
#define SLOPE_PIECE(uv) textureLod(u_slopes, uv, lod)
#else
    float bias = log2(footprint / implicit_long_side(p));
#define SLOPE_PIECE(uv) texture(u_slopes, uv, bias)
#endif
    vec4 slopes = vec4(0.0);
    // A do-while, not a for: every pixel takes at least one piece, and a loop that tests at
    // its top runs its body once more, masked off, after the last pixel's last piece on a
    // machine that runs neighbouring pixels in lockstep (llvmpipe: one wasted fetch per
    // cascade, 6 to 11 % of the ocean pass; ./ocean bench --against, docs/performance.md).
    int i = 0;
    do {
        slopes += SLOPE_PIECE(cascade_uv(p + long_axis * ((float(i) + 0.5) / float(taps) - 0.5), c));
    } while (++i < taps);
#undef SLOPE_PIECE
    s.slopes += slopes / float(taps);
    // The pixel's normal is the mean slope over its long x short footprint: what that averages
    // away is about what a square of the same area does (the level of sqrt(long x short)).
    s.unresolved_slope_variance += unresolved_at(c, cascade_lod(c, sqrt(long_length * max(short_length, texel))));
}

SurfaceSample sample_surface(vec2 p, SurfaceFootprint f) {
    float lx = length(f.dx), ly = length(f.dy);
    vec2 long_axis = lx > ly ? f.dx : f.dy;
    float long_length = max(lx, ly), short_length = min(lx, ly);
    SurfaceSample s;
    s.slopes = vec4(0.0);
    s.unresolved_slope_variance = 0.0;
    for (int c = 0; c < CASCADES; ++c) add_cascade(c, p, long_axis, long_length, short_length, s);
#if EXTRA_WAVES
    s.slopes += extra_slopes_at(p);
#endif
    return s;
}

// The foam at rest position p (fragment shaders), averaged over a footprint `long_side` metres
// long: (whitecaps' foam, residual foam), from the finest level whose window holds p, blended
// into the next one over the outer tenth of its window, none beyond the largest window. The
// windows nest with room to spare (foam.hpp), so a point is in one level's blending band at most:
// one fetch, two in a band. textureLod at the footprint's level over the level's texel, a level
// per pixel: neighbouring pixels may read different layers, and GL's level from their
// coordinates would be meaningless there. (Until issue 23's tenth stop every level was read, in
// uniform control flow, and the residual from a texture of its own: four fetches a pixel where
// there is now one: with the streaks compiled out below Beaufort 7, 7 to 13 % of the shading pass
// on llvmpipe; docs/performance.md.)
vec2 foam_at(vec2 p, float long_side) {
    // The finest level with weight, found from the coarsest down (arithmetic only).
    int level = FOAM_LEVELS - 1;
    float weight = 0.0, next_weight = 0.0, above = 0.0;  // above: the weight of level l + 1
    for (int l = FOAM_LEVELS - 1; l >= 0; --l) {
        vec2 offset = abs(p - u_foam_centre[l]);
        float inside = 0.5 * u_foam_extent[l] - max(offset.x, offset.y);  // metres from the edge
        float w = clamp(inside / (0.1 * u_foam_extent[l]), 0.0, 1.0);
        if (w > 0.0) {
            level = l;
            weight = w;
            next_weight = above;
        }
        above = w;
    }
    // The second fetch, for the band where a level hands over to the next, only where a pixel of
    // the group needs it: a do-while whose length the group agrees on. A machine that runs
    // neighbouring pixels in lockstep leaves a loop at its back edge once every pixel is done,
    // where an if runs both sides masked (llvmpipe).
    int fetches = weight < 1.0 && level + 1 < FOAM_LEVELS ? 2 : 1;
#ifdef GROUP_VOTES
    fetches = anyInvocationARB(fetches == 2) ? 2 : 1;
#endif
    float texels = float(textureSize(u_foam, 0).x);
    vec2 foam = vec2(0.0);
    int k = 0;
    do {
        int l = min(level + k, FOAM_LEVELS - 1);
        float w = k == 0 ? weight : (1.0 - weight) * next_weight;
        float lod = log2(max(long_side * texels / u_foam_extent[l], 1e-20));
        foam += w * textureLod(u_foam, vec3(p / u_foam_extent[l], float(l)), lod).rg;
    } while (++k < fetches);
    return foam;
}

// foam_pattern.hpp: r 1 on the borders of bubble cells; g a smooth noise; b r^2; a another noise
layout(binding = UNIT_FOAM_PATTERN) uniform sampler2D u_foam_pattern;
layout(binding = UNIT_STREAK_LINES) uniform sampler2D u_streak_lines;  // r: the streaks' line cover (foam_pattern.hpp's streak_line)
uniform float u_foam_pattern_size;  // metres one tile of it covers
// World (x, z) to the pattern's coordinates for the streaks: stretched along the wind.
uniform vec2 u_streak_along, u_streak_across;
#ifndef STREAKS
#define STREAKS 1  // 0: below Beaufort 7, no streaks (FoamSimulation::streaks())
#endif
// The streaks' frame (foam_pattern.hpp): metres along and across the wind to the line's pattern,
// the meander's and the breaks'; the streaks' strength (foam_streak_share).
uniform vec2 u_meander_along, u_meander_across, u_break_along, u_break_across;
uniform float u_streak_meander, u_streak_share;

// foam_pattern.hpp's net_cover: linear in the amount, the cells' middles open first; and its
// residual_cover: thin lace, torn unevenly by the smooth noise, never closed.
const float ACTIVE_HOLES = 0.3, RESIDUAL_HOLES = 0.75, RESIDUAL_THICKNESS = 0.9, RESIDUAL_MOST = 0.65,
            RESIDUAL_ALBEDO = 0.5;

// foam_pattern.hpp's mean_clamp and filtered_net_cover: the mean cover over a pixel's footprint,
// from the pattern's mean and variance there (the filtered r and b), so a lace far away is as
// bright on average as near (net_cover of the filtered mean would close or erase it).
float clamp_integral(float x) { return x <= 0.0 ? 0.0 : (x < 1.0 ? 0.5 * x * x : x - 0.5); }
float mean_clamp(float alpha, float beta, float mean, float variance) {
    float half_width = sqrt(3.0 * max(variance, 0.0)) * abs(beta);
    float centre = alpha + beta * mean;
    if (half_width < 1e-4) return clamp(centre, 0.0, 1.0);
    return (clamp_integral(centre + half_width) - clamp_integral(centre - half_width)) / (2.0 * half_width);
}
float filtered_net_cover(float amount, vec2 pattern, float holes) {  // pattern: (mean, variance)
    return mean_clamp((amount - holes) / (1.0 - holes), holes / (1.0 - holes), pattern.x, pattern.y);
}
// One pattern value (no spread): clamp((amount - (1 - pattern) holes) / (1 - holes), 0, 1).
float net_cover(float amount, float pattern, float holes) { return filtered_net_cover(amount, vec2(pattern, 0.0), holes); }
float residual_thickness(float amount, float noise) {
    return min(RESIDUAL_THICKNESS * (0.25 + 1.25 * noise) * amount, RESIDUAL_MOST);
}
float residual_cover(float amount, float pattern, float noise) {
    return net_cover(residual_thickness(amount, noise), pattern, RESIDUAL_HOLES);
}
// A fetch of the pattern as (mean, variance) over the footprint. The bytes' rounding leaves up to
// about 2/255 of false variance where the footprint is a texel: taken off.
vec2 pattern_statistics(vec4 texel) { return vec2(texel.r, max(texel.b - texel.r * texel.r - 2.0 / 255.0, 0.0)); }
// Two patterns mixed with weights w and 1 - w (independent: the variances add, squared weights).
vec2 mix_statistics(vec2 a, vec2 b, float w) { return vec2(w * a.x + (1.0 - w) * b.x, w * w * a.y + (1.0 - w) * (1.0 - w) * b.y); }

// foam_pattern.hpp's streaks: what a line gathers from about and upwind of it
// (streak_gathered), the foam's thickness on the line where it is not broken (streak_thickness),
// and the cover: the line's cover (read filtered from u_streak_lines, where the CPU wrote the ramp
// of the cells' pattern, foam_pattern.hpp's streak_line) times its foam laid on the bubble cells
// as lace is; linear in the line's cover, so the line's share of a footprint is exact.
const float BREAK_FROM = 0.3, BREAK_TO = 0.45;
const float STREAK_NEAR = 6.0, STREAK_FAR = 18.0, STREAK_FADE = 15.0, STREAK_MOST = 0.8, STREAK_HOLES = 0.75;
float streak_gathered(float here, float near, float far) {
    return max(here, max(near * exp(-STREAK_NEAR / STREAK_FADE), far * exp(-STREAK_FAR / STREAK_FADE)));
}
float streak_thickness(float gathered, float unbroken) {
    return clamp(3.0 * gathered, 0.0, STREAK_MOST) * smoothstep(BREAK_FROM, BREAK_TO, unbroken);
}

// How much of the pixel each stage of foam covers, and the active foam's brightness there: a
// breaking crest is churned, bubbles and troughs of foam, not a flat sheet.
struct FoamCover {
    float whitecap, residual;  // the active foam's cover, the residual's
    float turbulence;  // the active foam's albedo, per unit of fresh foam's: 0.8 to 1
};
// The simulated amounts laid out by the pattern in world space, where the foam is: the active
// foam on the pattern read at two scales (so the cells are not all one size and the tile does not
// show), the residual as lace on both, and from Beaufort 7 also as streaks.
FoamCover foam_cover(vec2 p, SurfaceFootprint f) {
    float long_side = max(length(f.dx), length(f.dy));
    vec2 amounts = foam_at(p, long_side);    // (active foam, foam as a whole)
#if STREAKS
    // What a line gathers: the wind's cells sweep the foam of the water between the lines into
    // them, so a line holds the foam of metres around it (the amounts read over a footprint
    // STREAK_NEAR wide), and of the water upwind, which the surface drift carries down the line,
    // fading with the distance it travelled: here, STREAK_NEAR and STREAK_FAR upwind.
    vec2 downwind = normalize(u_streak_along);
    float gathered = streak_gathered(foam_at(p, max(long_side, STREAK_NEAR)).y,
                                     foam_at(p - STREAK_NEAR * downwind, max(long_side, STREAK_NEAR)).y,
                                     foam_at(p - STREAK_FAR * downwind, max(long_side, STREAK_FAR)).y);
#else
    float gathered = 0.0;
#endif
    amounts.y = max(amounts.y - amounts.x, 0.0);  // the residual: what the active part is not
    // Most of the sea holds no foam that shows: an active amount below 0.002 covers under 0.005 of
    // any texel, and a residual below 0.02 (its thin lace: at most 0.027 thick) under 0.002 of a
    // pixel on average. There it skips the pattern: on a GPU a branch, on llvmpipe, which runs a
    // branch masked, a saving wherever a whole group of pixels skips it. The residual fades
    // slowly (10 s), so much of the sea holds a trace of it: without its own threshold the
    // pattern's fetches ran over most of the sea. The fetches take the footprint's own
    // derivatives (textureGrad), so a pixel with foam needs no neighbour to take the branch with it.
    if (amounts.x < 0.002 && amounts.y < 0.02 && gathered < 0.02) return FoamCover(0.0, 0.0, 1.0);
    vec2 uv = p / u_foam_pattern_size, uv_dx = f.dx / u_foam_pattern_size, uv_dy = f.dy / u_foam_pattern_size;
    // Foam on a sea that has stretched and sheared it: the cells are read through a warp of up to
    // half a metre, the two smooth noises (g, a) over 30 m tiles, so no honeycomb shows. Then the
    // cells at two scales (9 m and 3.3 m tiles), so they are not all one size and the tile does
    // not show: the active foam takes them 0.6 / 0.4, the residual's lace 0.55 / 0.45.
    vec4 noise = textureGrad(u_foam_pattern, uv * 0.3 + 0.21, uv_dx * 0.3, uv_dy * 0.3);
    vec2 lace_uv = uv + 0.12 * (noise.ga - 0.5);
    vec2 coarse = pattern_statistics(textureGrad(u_foam_pattern, lace_uv, uv_dx, uv_dy));
    vec2 fine = pattern_statistics(textureGrad(u_foam_pattern, lace_uv * 2.71 + 0.37, uv_dx * 2.71, uv_dy * 2.71));
    float active_cover = filtered_net_cover(amounts.x, mix_statistics(coarse, fine, 0.6), ACTIVE_HOLES);
    // The residual's lace: thin foam (residual_thickness): the water shows through its holes, and
    // they open as it fades, unevenly: the noise makes it denser in some places than in others,
    // as a raft of foam tears.
    float residual = filtered_net_cover(residual_thickness(amounts.y, noise.g), mix_statistics(coarse, fine, 0.55), RESIDUAL_HOLES);
#if STREAKS
    // The streaks: the line's cover stretched along the wind, its across coordinate shifted by
    // the meander (the smooth noise), cut where the smooth noise is low. (Rows of each matrix:
    // along, across.) The texture filter averages the line's cover itself over the footprint.
    mat2 to_meander = transpose(mat2(u_meander_along, u_meander_across));
    mat2 to_breaks = transpose(mat2(u_break_along, u_break_across));
    mat2 to_lines = transpose(mat2(u_streak_along, u_streak_across));
    float wander = textureGrad(u_foam_pattern, to_meander * p, to_meander * f.dx, to_meander * f.dy).g;
    float unbroken = textureGrad(u_foam_pattern, to_breaks * p, to_breaks * f.dx, to_breaks * f.dy).g;
    vec2 across = normalize(u_streak_across);  // the meander moves the point across the wind
    vec2 q = p + across * (u_streak_meander * (2.0 * wander - 1.0));
    float line = textureGrad(u_streak_lines, to_lines * q, to_lines * f.dx, to_lines * f.dy).r;  // the line's cover
    // A streak is foam gathered into a line: three times what it gathered, laid on the same
    // bubble cells as the lace (flat foam with holes, not a solid bar), over the share of the
    // footprint the line covers; the lace loses part of what the wind gathered (foam_pattern.hpp).
    float streak = line * filtered_net_cover(streak_thickness(gathered, unbroken), mix_statistics(coarse, fine, 0.55), STREAK_HOLES);
    residual = max(residual * (1.0 - 0.8 * u_streak_share), u_streak_share * streak);
#endif
    return FoamCover(active_cover, residual, 0.8 + 0.2 * fine.x);
}
