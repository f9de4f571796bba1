#version 450 core
// Evaluates step06's foam_cover at every texel of the bubble pattern, for the read-back test.
#include "step06_foam_sky/shaders/cascades_visible.glsl"

out float out_cover;
uniform float u_amount;

void main() {
    out_cover = foam_cover(u_amount, texelFetch(u_foam_pattern, ivec2(gl_FragCoord.xy), 0).r);
}
