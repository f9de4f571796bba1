#version 450 core
// The waterline, pixel by pixel: a pixel's ray starts on the camera's lens (the near plane), and
// the pixel is drawn from the side of the surface that point is on. Which side is found from the
// water's height there: the surface is the rest grid moved by the waves, so the water above a point
// x is the height of the rest position a that the waves carry to x, a + D(a) = x, found by
// iterating a <- x - D(a) (the horizontal displacement is a fraction of the distance between
// crests: the iteration converges where the waves do not fold over).
#include "step06_foam_sky/shaders/cascades.glsl"
#include "step10_underwater/underwater_units.h"

in vec2 v_uv;
out vec4 out_colour;
uniform mat4 u_inverse_view_projection;  // from the sea's world origin
uniform bool u_keep_below;  // draw the pixels whose lens point is below the water (else above)
uniform bool u_paint;       // the sides view: the side's colour, not the picture below
layout(binding = UNIT_BELOW_PICTURE) uniform sampler2D u_below;

// The lens is centimetres across: every cascade at its finest level.
const float LENS_FOOTPRINT = 0.01;

float water_height_at(vec2 x) {
    vec2 a = x;
    for (int i = 0; i < 4; ++i) a = x - displacement_at(a, LENS_FOOTPRINT).xz;
    return displacement_at(a, LENS_FOOTPRINT).y;
}

void main() {
    vec4 lens = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, -1.0, 1.0);
    vec3 p = lens.xyz / lens.w;
    float above = p.y - water_height_at(p.xz);
    // Two tests, not one and its negation: a height that is not a number keeps the pixel on
    // neither side, which the sides view shows (green) and the tests count.
    bool keep = u_keep_below ? above < 0.0 : above >= 0.0;
    if (!keep) discard;
    if (u_paint) out_colour = u_keep_below ? vec4(0.0, 0.0, 1.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
    else out_colour = texelFetch(u_below, ivec2(gl_FragCoord.xy), 0);
}
