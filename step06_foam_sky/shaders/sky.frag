#version 450 core
// The background: the sky cubemap along each pixel's view ray (linear HDR, like the sea), and the
// sun's disc, which the cubemap leaves out (sky.glsl says why).
#include "step06_foam_sky/texture_units.h"
#include "sky.glsl"

in vec2 v_uv;
out vec4 out_colour;

layout(binding = UNIT_SKY) uniform samplerCube u_sky;
uniform mat4 u_inverse_view_projection;
uniform bool u_draw_sun_disc;  // not over a sky image (its sun is in the picture)

void main() {
    vec4 far = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
    vec4 near = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, -1.0, 1.0);
    vec3 direction = normalize(far.xyz / far.w - near.xyz / near.w);
    vec3 colour = textureLod(u_sky, direction, 0.0).rgb;
    if (u_draw_sun_disc) colour += sun_disc(direction);
    out_colour = vec4(colour, 1.0);
}
