#version 450 core
// Evaluates step06's foam_at (whitecaps' and residual foam, from the clipmap) on a grid of points
// over the foam's windows, for the read-back test against foam.hpp's foam_level_weights.
#include "step06_foam_sky/shaders/cascades_visible.glsl"

out vec2 out_foam;
uniform vec2 u_first;  // metres (x, z) of pixel (0, 0)
uniform float u_step;  // metres from a pixel to the next

void main() {
    vec2 p = u_first + (gl_FragCoord.xy - 0.5) * u_step;
    out_foam = foam_at(p, u_step);
}
