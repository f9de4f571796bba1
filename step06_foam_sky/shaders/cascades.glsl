// The four cascades' textures (step05's simulation, one layer each) and what the surface is at a
// rest position p: the sum of the cascades, each sampled at p over its own tile size.
#include "step05_fft/shaders/ocean_maps.glsl"

const int CASCADES = 4;
uniform float u_patch_sizes[CASCADES];  // metres
uniform bool u_cascade_enabled[CASCADES];
uniform sampler2DArray u_foam;          // one layer per cascade

// (l Dx, h, l Dz, l dDx/dz) summed over the cascades, at mip level `lod` (any stage).
vec4 total_displacement(vec2 p, float lod) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c)
        if (u_cascade_enabled[c]) sum += textureLod(u_displacement, vec3(p / u_patch_sizes[c], float(c)), lod);
    return sum;
}

