#version 450 core
// Chapter 5.3 (foam.hpp is the CPU reference): at each texel of each foam level, the Jacobian of
// the summed surface (all cascades, as rendered) at the texel's rest position; foam is made where
// J falls below the threshold, and remembered by two clocks: the active foam (first channel) fades
// fast, the foam as a whole (second channel) slowly; the residual foam is their difference. Both
// integrated exactly over the frame (foam_step.glsl). A fragment pass, drawn once a level into that
// level's layer of one texture while it reads last frame's foam from the other (a ping-pong: a
// texture is never read and written by one draw), so it runs where there are no compute shaders.
#include "cascades.glsl"
// FOAM_LEVELS and the clipmap's layout:
#include "foam_map.glsl"
#include "foam_step.glsl"

uniform sampler2DArray u_foam_before;  // last frame's (active foam, foam as a whole), a layer per level
uniform int u_level;                   // the level (layer) this draw writes

layout(location = 0) out vec4 foam_out;  // (active foam, foam as a whole) into the level's layer

uniform int u_n;                                // texels per side of a level (a power of two)
uniform ivec2 u_origin[FOAM_LEVELS];            // the window's first cell, in texels of its level, from the world origin
uniform ivec2 u_previous_origin[FOAM_LEVELS];   // the same, last frame
uniform float u_texel_size[FOAM_LEVELS];        // metres
uniform float u_dt;
uniform float u_threshold;
uniform float u_injection;
uniform float u_decay_rate;      // r_a: the active foam's
uniform float u_residual_decay;  // r_b: the foam's as a whole
uniform bool u_warm_start;  // a new foam texture: start from the steady state of this J

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int level = u_level;
    // The world cell this texel holds: the one in [origin, origin + n) congruent to it mod n.
    ivec2 origin = u_origin[level];
    ivec2 cell = origin + ((texel - origin) & (u_n - 1));
    vec2 p = (vec2(cell) + 0.5) * u_texel_size[level];

    // Every level reads the surface as finely as the finest level does, at its texel's centre: the
    // same field, sampled more sparsely farther out. Read at its own texel's size, a coarse level
    // would see the folds smoothed away and make less foam (a 1 m texel made a third of the foam a
    // 0.25 m one did): the sea seen from the deck, through the finer level, would carry more foam
    // than the same sea from above, through the coarser one. Sparse samples are not smooth, but they
    // are unbiased, and they sit still in the world (the windows move by whole texels).
    vec4 displacement, slopes;
    surface_at(p, u_texel_size[0], displacement, slopes);
    float j = jacobian(displacement, slopes);

    // A cell that has just entered the window holds another cell's foam: start it afresh.
    ivec2 previous = u_previous_origin[level];
    bool entered = any(lessThan(cell, previous)) || any(greaterThanEqual(cell, previous + u_n));
    float injection_rate = u_injection * max(0.0, u_threshold - j);
    bool fresh = u_warm_start || entered;  // start where injection and decay balance if J stayed as it is
    vec2 rates = vec2(u_decay_rate, u_residual_decay);
    vec2 foam;
    if (fresh) {
        foam = clamp(injection_rate / max(rates, vec2(0.1)), 0.0, 1.0);
    } else {
        vec2 before = texelFetch(u_foam_before, ivec3(texel, level), 0).rg;
        foam = vec2(foam_step(before.x, injection_rate, rates.x, u_dt), foam_step(before.y, injection_rate, rates.y, u_dt));
    }
    foam_out = vec4(foam, 0.0, 0.0);
}
