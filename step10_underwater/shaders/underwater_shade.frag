#version 450 core
// The sea's surface seen from below, at every pixel where the mesh wrote depth (step06's G-buffer,
// drawn at the far plane with the GREATER test, as step06's shading is). At the surface the light
// from above and the light from below meet:
//   - the sky, through the surface: refracted (Snell, n = 1.333 to 1), times the transmitted
//     fraction 1 - R and n^2 (radiance over n^2 is what a ray keeps across a surface, so the sky
//     seen from below is brighter, squeezed into Snell's window);
//   - the depths, mirrored: R of the water's light from below, and all of it past the critical
//     angle (total internal reflection);
// then both cross the water to the eye.
#include "step06_foam_sky/texture_units.h"
#include "step06_foam_sky/shaders/cascades_visible.glsl"
#include "step06_foam_sky/shaders/half_pack.glsl"
#include "underwater_view.glsl"

layout(binding = UNIT_GBUFFER_WORLD) uniform sampler2D u_gbuffer_world;
layout(binding = UNIT_GBUFFER_REST) uniform usampler2D u_gbuffer_rest;
layout(binding = UNIT_SKY) uniform samplerCube u_sky;
uniform vec3 u_eye;  // metres from the sea's world origin

out vec4 out_colour;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 world = texelFetch(u_gbuffer_world, pixel, 0);
    uvec4 packed_rest = texelFetch(u_gbuffer_rest, pixel, 0);
    vec2 rest_xz = uintBitsToFloat(packed_rest.xy);
    SurfaceFootprint footprint = SurfaceFootprint(unpack_halves(packed_rest.z), unpack_halves(packed_rest.w));
    SurfaceSample surface = sample_surface(rest_xz, footprint);
    vec3 n = choppy_normal(vec4(0.0, 0.0, 0.0, world.w), surface.slopes);  // up, the air's side

    vec3 to_surface = world.xyz - u_eye;
    float t = length(to_surface);
    vec3 d = to_surface / t;  // from the eye, up to the surface
    float cos_i = dot(d, n);
    if (cos_i < 0.0) { n = -n; cos_i = -cos_i; }  // a facet seen edge-on from its far side
    float r = fresnel_from_water(cos_i);
    vec3 light = vec3(0.0);
    vec3 out_of_water = refract(d, -n, WATER_INDEX);  // zero past the critical angle
    if (r < 1.0) light += (1.0 - r) * WATER_INDEX * WATER_INDEX * textureLod(u_sky, out_of_water, 0.0).rgb;
    vec3 mirrored = reflect(d, -n);
    light += r * water_ray(world.xyz, mirrored, 1e4);
    float depth = max(-u_eye.y, 0.0);
    out_colour = vec4(u_below_exposure * (light * exp(-extinction() * t) + inscatter(depth, d, t)), 1.0);
}
