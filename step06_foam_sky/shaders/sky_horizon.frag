#version 450 core
// The fog's colour table (sky_horizon.glsl), one row of HORIZON_TEXELS: texel i holds the sky
// cube, at the blurred level the fog takes, in the horizontal direction of the texel's centre.
#include "sky_horizon.glsl"

layout(binding = UNIT_SKY) uniform samplerCube u_sky;
uniform float u_lod;  // Sky::horizon_lod

layout(location = 0) out vec4 colour;

void main() {
    vec2 d = normalize(horizon_direction(gl_FragCoord.x / float(HORIZON_TEXELS)));
    colour = textureLod(u_sky, vec3(d.x, 0.0, d.y), u_lod);
}
