#version 450 core
// Evaluates step06's cover functions (cascades_visible.glsl) at every texel of the pattern texture,
// for the read-back test: net_cover with the given holes, residual_cover (the cells' pattern and
// the smooth noise of that texel), streak_thickness (the noise as the breaks) or streak_gathered
// (u_amount here, the pattern and the noise as the foam near and
// far upwind); or, drawn at the size of mip level u_lod, filtered_net_cover on that level's
// texels (the pattern's mean and variance over what each averages), or the line cover as the
// renderer reads it (u_streak_lines).
#include "step06_foam_sky/shaders/cascades_visible.glsl"

out float out_cover;
uniform float u_amount;
uniform float u_holes;
uniform int u_function;  // 0 net_cover, 1 residual_cover, 2 streak_thickness, 3 filtered_net_cover,
                         // 4 the line cover read, 5 streak_gathered
uniform float u_lod;     // 3 and 4: the mip level read

void main() {
    if (u_function == 3 || u_function == 4) {
        // textureLod as the renderer reads the pattern, at the centre of one texel of the level:
        // the filter returns that texel alone. The breaks' factor is 1: it multiplies, unfiltered
        // (streak_thickness's test, 2, has it).
        vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_foam_pattern, int(u_lod)));
        vec2 pattern = pattern_statistics(textureLod(u_foam_pattern, uv, u_lod));
        out_cover = u_function == 3 ? filtered_net_cover(u_amount, pattern, u_holes) : textureLod(u_streak_lines, uv, u_lod).r;
        return;
    }
    vec2 texel = texelFetch(u_foam_pattern, ivec2(gl_FragCoord.xy), 0).rg;
    out_cover = u_function == 0 ? net_cover(u_amount, texel.r, u_holes)
              : u_function == 1 ? residual_cover(u_amount, texel.r, texel.g)
              : u_function == 2 ? streak_thickness(u_amount, texel.g)
                                : streak_gathered(u_amount, texel.r, texel.g);
}
