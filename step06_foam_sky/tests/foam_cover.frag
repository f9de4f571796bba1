#version 450 core
// Evaluates step06's cover functions (cascades_visible.glsl) at every texel of the pattern texture,
// for the read-back test: net_cover with the given holes, residual_cover (the cells' pattern and
// the smooth noise of that texel), or streak_cover (the cells' pattern as the line, the noise as
// the breaks).
#include "step06_foam_sky/shaders/cascades_visible.glsl"

out float out_cover;
uniform float u_amount;
uniform float u_holes;
uniform int u_function;  // 0 net_cover, 1 residual_cover, 2 streak_cover

void main() {
    vec2 texel = texelFetch(u_foam_pattern, ivec2(gl_FragCoord.xy), 0).rg;
    out_cover = u_function == 0 ? net_cover(u_amount, texel.r, u_holes)
              : u_function == 1 ? residual_cover(u_amount, texel.r, texel.g)
                                : streak_cover(u_amount, texel.r, texel.g);
}
