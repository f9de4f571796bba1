#version 450 core
// Evaluates extra_waves.glsl (EXTRA_WAVES 1) on a grid of points over the extra waves' grid and
// past its edges, for the read-back tests against extra_waves.hpp's extra_waves_at (in double).
#define EXTRA_WAVES 1
#include "step06_foam_sky/shaders/extra_waves.glsl"

out vec4 out_map;
uniform vec2 u_first;    // metres (x, z) from the world origin of pixel (0, 0)
uniform float u_step;    // metres from a pixel to the next
uniform int u_slopes;    // 0: the displacement map; 1: the slopes

void main() {
    vec2 p = u_first + (gl_FragCoord.xy - 0.5) * u_step;
    out_map = u_slopes == 1 ? extra_slopes_at(p) : extra_displacement_at(p);
}
