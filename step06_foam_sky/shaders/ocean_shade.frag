#version 450 core
// Deferred shading's second pass (ocean_shade.glsl): a full-screen triangle at the far plane,
// whose depth test (GREATER) keeps it to the pixels where the mesh wrote depth.
#include "ocean_shade.glsl"

out vec4 out_colour;

void main() { out_colour = shade_sea_pixel(ivec2(gl_FragCoord.xy)); }
