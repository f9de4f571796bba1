#version 450 core
// Evaluates step06's foam_cover (or streak_cover) at every texel of the bubble pattern, for the
// read-back test.
#include "step06_foam_sky/shaders/cascades_visible.glsl"

out float out_cover;
uniform float u_amount;
uniform bool u_evaluate_streaks;  // streak_cover instead of foam_cover

void main() {
    float pattern = texelFetch(u_foam_pattern, ivec2(gl_FragCoord.xy), 0).r;
    out_cover = u_evaluate_streaks ? streak_cover(u_amount, pattern) : foam_cover(u_amount, pattern);
}
