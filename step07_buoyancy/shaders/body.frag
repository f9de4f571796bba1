#version 450 core
// A floating body, painted and matte: lit by the sun (Lambert) and by the sky it faces (the sky
// cube's coarsest level, as step06 lights its foam), under step06's height fog. Linear HDR.
#include "step06_foam_sky/texture_units.h"
#include "step06_foam_sky/shaders/fog.glsl"
#include "step06_foam_sky/shaders/sky_horizon.glsl"

in vec3 v_position, v_normal;
out vec4 out_colour;

uniform vec3 u_colour;  // linear albedo
uniform vec3 u_to_sun, u_sun_radiance, u_eye;
uniform float u_sky_max_lod;
uniform bool u_show_fog;
layout(binding = UNIT_SKY) uniform samplerCube u_sky;

const float PI = 3.14159265358979;

void main() {
    vec3 n = normalize(v_normal);
    vec3 sky = textureLod(u_sky, n, u_sky_max_lod).rgb;
    vec3 colour = u_colour * (sky + u_sun_radiance * max(dot(n, u_to_sun), 0.0) / PI);
    vec3 v = normalize(u_eye - v_position);
    if (u_show_fog) colour = apply_fog(colour, u_eye, v_position, horizon_colour(-v));
    out_colour = vec4(colour, 1.0);
}
