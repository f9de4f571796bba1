#version 450 core
// Chapter 5.3 (foam.hpp is the CPU reference): at each texel of each foam level, the Jacobian of
// the summed surface (all cascades, as rendered) at the texel's world position; foam is made where
// J falls below the threshold and fades, integrated exactly over the frame (foam_step.glsl). Beside
// it, in the texel's second channel, the residual foam a storm leaves, fed by a share of the same
// breaking and fading slowly (foam_pattern.hpp: the streaks).
layout(local_size_x = 8, local_size_y = 8) in;
#include "cascades.glsl"
// FOAM_LEVELS and the clipmap's layout:
#include "foam_map.glsl"
#include "foam_step.glsl"

#ifndef STREAKS
#define STREAKS 1  // 0: below Beaufort 7, the residual held at 0 (FoamSimulation::streaks())
#endif

layout(rg32f, binding = 0) uniform image2DArray u_foam_image;  // (whitecaps' foam, residual foam), a layer per level

uniform int u_n;                                // texels per side of a level (a power of two)
uniform ivec2 u_origin[FOAM_LEVELS];            // the window's first cell, in texels of its level, from the world origin
uniform ivec2 u_previous_origin[FOAM_LEVELS];   // the same, last frame
uniform float u_texel_size[FOAM_LEVELS];        // metres
uniform float u_dt;
uniform float u_threshold;
uniform float u_injection;
uniform float u_decay_rate;
uniform float u_streak_injection;  // the injection times foam_streak_share(U): 0 below Beaufort 7
uniform float u_streak_decay;
uniform bool u_warm_start;  // a new foam texture: start from the steady state of this J

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (id.x >= u_n || id.y >= u_n || id.z >= FOAM_LEVELS) return;
    int level = id.z;
    // The world cell this texel holds: the one in [origin, origin + n) congruent to it mod n.
    ivec2 origin = u_origin[level];
    ivec2 cell = origin + ((id.xy - origin) & (u_n - 1));
    vec2 p = (vec2(cell) + 0.5) * u_texel_size[level];

    vec4 displacement, slopes;
    surface_at(p, u_texel_size[level], displacement, slopes);
    float j = jacobian(displacement, slopes);

    // A cell that has just entered the window holds another cell's foam: start it afresh.
    ivec2 previous = u_previous_origin[level];
    bool entered = any(lessThan(cell, previous)) || any(greaterThanEqual(cell, previous + u_n));
    float squeeze = max(0.0, u_threshold - j);
    float injection_rate = u_injection * squeeze, streak_rate = u_streak_injection * squeeze;
    bool fresh = u_warm_start || entered;  // start where injection and decay balance if J stayed as it is
    vec2 before = fresh ? vec2(0.0) : imageLoad(u_foam_image, id).rg;
    float foam = fresh ? clamp(injection_rate / max(u_decay_rate, 0.1), 0.0, 1.0)
                       : foam_step(before.r, injection_rate, u_decay_rate, u_dt);
    // Below Beaufort 7 (STREAKS 0) there is no streak injection: the residual is held at 0, so it
    // starts from none when the streaks come back.
#if STREAKS
    float residual = fresh ? clamp(streak_rate / max(u_streak_decay, 0.1), 0.0, 1.0)
                           : foam_step(before.g, streak_rate, u_streak_decay, u_dt);
#else
    float residual = 0.0;
#endif
    imageStore(u_foam_image, id, vec4(foam, residual, 0.0, 0.0));
}
