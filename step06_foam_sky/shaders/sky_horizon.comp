#version 450 core
// The fog's colour table (sky_horizon.glsl): texel i holds the sky cube, at the blurred level the
// fog takes, in the horizontal direction of the texel's centre.
layout(local_size_x = 64) in;
#include "sky_horizon.glsl"

layout(binding = UNIT_SKY) uniform samplerCube u_sky;
layout(rgba32f, binding = 0) writeonly uniform image1D u_horizon_image;
uniform float u_lod;  // Sky::horizon_lod

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= HORIZON_TEXELS) return;
    vec2 d = normalize(horizon_direction((float(i) + 0.5) / float(HORIZON_TEXELS)));
    imageStore(u_horizon_image, i, textureLod(u_sky, vec3(d.x, 0.0, d.y), u_lod));
}
