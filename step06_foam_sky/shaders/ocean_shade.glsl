// Deferred shading, second pass (gbuffer.hpp): each pixel of the sea shaded once, from what the
// mesh (ocean.frag) recorded there. Everything at a point of the sea: normal from the summed
// slopes, foam, scatter, microfacet specular, the sky's reflection weighted by Fresnel, and
// height fog. Output: linear HDR. ocean_shade.frag runs it at every pixel the sea covers.
#include "step06_foam_sky/texture_units.h"
#include "cascades_visible.glsl"
#include "half_pack.glsl"
#include "shading.glsl"
#include "fog.glsl"
#include "sky_horizon.glsl"
#include "level_colour.glsl"

#ifndef DEBUG_VIEW
#define DEBUG_VIEW 0  // 0 shaded; 1 normals; 2 foam; 3 Jacobian; 4 tessellation level
#endif

layout(binding = UNIT_GBUFFER_WORLD) uniform sampler2D u_gbuffer_world;   // (surface point, l dDx/dz; the level for DEBUG_VIEW 4)
layout(binding = UNIT_GBUFFER_REST) uniform usampler2D u_gbuffer_rest;   // (rest position, its d/dx and d/dy as half pairs)
uniform vec3 u_eye;
uniform vec3 u_to_sun;
uniform vec3 u_sun_radiance;
uniform vec3 u_ambient;
layout(binding = UNIT_SKY) uniform samplerCube u_sky;
uniform float u_sky_max_lod;
uniform float u_roughness;  // a floor on alpha; the waves the pixel does not show add their slope variance
// The slope variance of the waves shorter than the last cascade (short_waves.hpp), along the
// wind and across it, and the wind's heading (x, z).
uniform vec2 u_short_wave_slope_variance;
uniform vec2 u_wind_heading;
uniform float u_height_scale;          // metres that count as a full crest for the scatter term
uniform vec3 u_scatter_colour, u_bubble_colour, u_foam_colour, u_crest_colour;
uniform float u_scatter_crest, u_scatter_view, u_scatter_lambert, u_scatter_bubbles;
uniform float u_foam_roughness;
// Toggles, so every term can be seen alone or left out.
uniform bool u_show_ambient, u_show_scatter, u_show_specular, u_show_reflection, u_show_foam, u_show_fog;

// Light a thin foam layer lets through towards the viewer: the share sent on (FOAM_FORWARD) times
// the phase function of bubbles, strongly forward (g = 0.6: the light is turned by tens of degrees,
// not reversed). cos_angle is between the sunlight's direction of travel and the view ray's.
const float FOAM_FORWARD = 0.5, FOAM_FORWARD_G = 0.6;
float henyey_greenstein(float cos_angle, float g) {
    return (1.0 - g * g) / (4.0 * PI * pow(1.0 + g * g - 2.0 * g * cos_angle, 1.5));
}

vec4 shade_sea_pixel(ivec2 pixel) {
    vec4 world = texelFetch(u_gbuffer_world, pixel, 0);
    uvec4 packed_rest = texelFetch(u_gbuffer_rest, pixel, 0);
    vec3 surface_point = world.xyz;
    vec2 rest_xz = uintBitsToFloat(packed_rest.xy);
    SurfaceFootprint footprint = SurfaceFootprint(unpack_halves(packed_rest.z), unpack_halves(packed_rest.w));
    SurfaceSample surface = sample_surface(rest_xz, footprint);
    // The slopes per pixel; the choppy cross term l dDx/dz interpolated from the mesh's vertices
    // (ocean.frag says why). choppy_normal and jacobian read only its w.
    vec4 displacement = vec4(0.0, 0.0, 0.0, world.w), slopes = surface.slopes;
    vec3 n = choppy_normal(displacement, slopes);
    vec3 to_eye = u_eye - surface_point;
    float distance = length(to_eye);
    vec3 v = to_eye / distance;
    if (dot(n, v) < 0.0) n = normalize(n + v * (0.01 - dot(n, v)));  // a normal facing away: bend it back
    // The two stages' cover (active whitecap, residual foam), and how much of the pixel foam
    // covers in all: the residual shows where the active foam leaves room.
    FoamCover cover = FoamCover(0.0, 0.0, 1.0);  // not a ?: : WebGL allows no ternary on a struct
    if (u_show_foam) cover = foam_cover(rest_xz, footprint);
    float foam = cover.whitecap + cover.residual * (1.0 - cover.whitecap);
    // How much of the light reaching the pixel its foam sends back, per unit of fresh foam's: the
    // breaking core's turbulence varies it a little, the residual is thinner (foam_pattern.hpp's
    // kResidualAlbedo). Bubbles scatter, they hardly absorb: what foam does not send back passes
    // through, so the water's own light shows through it in that measure.
    float foam_albedo = cover.whitecap * cover.turbulence + RESIDUAL_ALBEDO * cover.residual * (1.0 - cover.whitecap);

#if DEBUG_VIEW == 1
    return vec4(0.5 * n + 0.5, 1.0);
#elif DEBUG_VIEW == 2
    return vec4(vec3(foam_albedo), 1.0);
#elif DEBUG_VIEW == 3
    float j = jacobian(displacement, slopes);
    return vec4(j < 0.0 ? vec3(1.0, 0.0, 0.0) : vec3(clamp(j, 0.0, 2.0) * 0.5), 1.0);
#elif DEBUG_VIEW == 4
    return vec4(level_colour(world.w), 1.0);  // the mesh wrote the level there (LEVEL_VIEW)
#endif

    // Waves too small for this pixel are not lost: their slopes become microfacets, and so do the
    // waves shorter than any cascade (down to the capillaries). A Beckmann surface of roughness
    // alpha has slope variance alpha^2 / 2 along each axis, so a variance sigma^2 along an axis
    // adds 2 sigma^2 to that axis's alpha^2 (GGX is given the same alphas). The pixel's unresolved
    // variance (both axes summed) is spread evenly; the short waves' is split along and across the
    // wind, as Cox and Munk measured it.
    float isotropic_alpha2 = u_roughness * u_roughness + surface.unresolved_slope_variance;
    Roughness roughness = wind_roughness(n, sqrt(isotropic_alpha2 + 2.0 * u_short_wave_slope_variance.x),
                                         sqrt(isotropic_alpha2 + 2.0 * u_short_wave_slope_variance.y), u_wind_heading);
    roughness.along = mix(roughness.along, u_foam_roughness, foam);
    roughness.across = mix(roughness.across, u_foam_roughness, foam);
    float alpha = sqrt(0.5 * (roughness.along * roughness.along + roughness.across * roughness.across));
    const float f0 = 0.02;
    float fresnel = fresnel_schlick(dot(n, v), f0);

    vec3 r = reflect(-v, n);
    r.y = abs(r.y);  // a reflection pointing into the sea sees the sky it mirrors
    vec3 sky = textureLod(u_sky, r, alpha * u_sky_max_lod).rgb;

    ScatterSettings s = ScatterSettings(u_scatter_crest, u_scatter_view, u_scatter_lambert, u_scatter_bubbles, u_scatter_colour, u_bubble_colour, u_crest_colour);
    float height = surface_point.y / u_height_scale;
    vec3 water = vec3(0.0);
    if (u_show_ambient) water += (1.0 - fresnel) * u_ambient * u_scatter_colour;
    if (u_show_scatter) water += (1.0 - fresnel) * scatter_term(n, v, u_to_sun, height, roughness, foam, s, u_sun_radiance);
    if (u_show_reflection) water += fresnel * sky;
    if (u_show_specular) water += specular_term(n, v, u_to_sun, roughness, f0, u_sun_radiance);
    // Foam is a layer of bubbles, white because the light it receives is: its colour is the
    // light's, times an albedo. It sends back what it receives almost diffusely (Lambertian,
    // f_r = albedo / pi): the sky it faces, whose irradiance over pi is the sky's mean radiance over
    // the hemisphere around n (the cube's coarsest level, read at n, stands for it; the same sky
    // the water reflects), and the sun. The bubbles face every way, so the layer takes the sun's
    // light half as the facet does (n.l) and half as a level layer would (l.y). And a thin layer
    // lets light through, mostly forwards (bubbles scatter forwards, as cloud droplets do): seen
    // against a low sun, foam glows (Henyey-Greenstein's phase, g = FOAM_FORWARD_G).
    // Only where there is foam (most pixels have none; textureLod needs no neighbours).
    vec3 colour = water;
    if (foam > 0.0) {
        vec3 sky_irradiance_over_pi = textureLod(u_sky, n, u_sky_max_lod).rgb;
        float sun_on_layer = 0.5 * max(dot(n, u_to_sun), 0.0) + 0.5 * max(u_to_sun.y, 0.0);
        float through = FOAM_FORWARD * henyey_greenstein(dot(-v, u_to_sun), FOAM_FORWARD_G);
        vec3 foam_light = u_foam_colour * (sky_irradiance_over_pi + u_sun_radiance * (sun_on_layer / PI + through));
        colour = water * (1.0 - foam_albedo) + foam_light * foam_albedo;
    }
    if (u_show_fog) colour = apply_fog(colour, u_eye, surface_point, horizon_colour(-v));
    return vec4(colour, 1.0);
}
