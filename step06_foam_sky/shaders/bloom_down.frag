#version 450 core
// Bloom, down the chain: each level is half the previous, filtered by the 13-tap downsample of
// Jimenez (Call of Duty: Advanced Warfare, SIGGRAPH 2014): 13 bilinear fetches at 0, +-1 and
// +-2 source texels, i.e. five overlapping 4x4 boxes (the centre one weighted 1/2, the four
// corner ones 1/8 each), 36 texels in all. A plain 2x2 box would alias: a thin bright line
// flickers as it crosses texel boundaries.
// The first pass goes from the screen to a quarter of it each way and keeps only what is brighter
// than the threshold (a soft knee), so only the sun, its glint and bright foam bloom. Its filter
// is 9 bilinear fetches 2 screen pixels apart: each averages the 2x2 pixels around a pixel corner,
// and their (1 2 1) x (1 2 1) weights make a 6x6 tent-shaped filter over the 4x4 block and its
// border, so the glow of a one-pixel glint follows it in steps of 2 pixels, within 3/4 of a pixel
// (a 4x4 box: steps of 4, 1.7 pixels off). bloom.hpp is the CPU reference.
in vec2 v_uv;
out vec4 out_colour;

uniform sampler2D u_source;
uniform vec2 u_source_texel;  // 1 / source size
uniform float u_threshold;

vec3 tap(float x, float y) { return texture(u_source, v_uv + vec2(x, y) * u_source_texel).rgb; }

vec3 quarter_size_tent() {
    vec3 middle = tap(0.0, 0.0);
    vec3 sides = tap(-2.0, 0.0) + tap(2.0, 0.0) + tap(0.0, -2.0) + tap(0.0, 2.0);
    vec3 corners = tap(-2.0, -2.0) + tap(2.0, -2.0) + tap(-2.0, 2.0) + tap(2.0, 2.0);
    return 0.25 * middle + 0.125 * sides + 0.0625 * corners;
}

vec3 half_size_13_taps() {
    vec3 centre = tap(0.0, 0.0);
    vec3 inner = tap(-1.0, -1.0) + tap(1.0, -1.0) + tap(-1.0, 1.0) + tap(1.0, 1.0);
    vec3 edges = tap(0.0, -2.0) + tap(-2.0, 0.0) + tap(2.0, 0.0) + tap(0.0, 2.0);
    vec3 corners = tap(-2.0, -2.0) + tap(2.0, -2.0) + tap(-2.0, 2.0) + tap(2.0, 2.0);
    // Weights: centre box 0.5 over its 4 inner taps; each corner box 0.125 over its 4 taps, which
    // share the centre, edge and inner taps: 0.125 + 4 * 0.03125 + 4 * 0.0625 + 4 * 0.125 = 1.
    return 0.125 * centre + 0.125 * inner + 0.0625 * edges + 0.03125 * corners;
}

// What is brighter than the threshold, with a soft knee below it.
vec3 above_threshold(vec3 c) {
    float brightness = max(c.r, max(c.g, c.b));
    float knee = 0.5 * u_threshold;
    float soft = clamp(brightness - u_threshold + knee, 0.0, 2.0 * knee);
    soft = soft * soft / (4.0 * knee + 1e-5);
    c *= max(soft, brightness - u_threshold) / max(brightness, 1e-5);
    return min(c, vec3(64.0));  // one sun texel must not become a huge square
}

#ifndef FIRST_LEVEL
#define FIRST_LEVEL 0  // 1: the first pass, from the screen (a define, not a uniform: llvmpipe runs
#endif                 // both sides of a branch on a uniform, which cost the chain 40 %)

void main() {
#if FIRST_LEVEL
    vec3 c = above_threshold(quarter_size_tent());
#else
    vec3 c = half_size_13_taps();
#endif
    out_colour = vec4(c, 1.0);
}
