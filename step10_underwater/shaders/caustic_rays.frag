#version 450 core
// Caustics, first pass: the sun's rays, one per texel of a grid, each refracted where it meets the
// moving surface (step06's cascades, read as its mesh reads them) and carried straight down to
// the seabed. Each texel keeps where its ray came from and where it landed, for the passes that
// gather the light (caustic_cells.glsl).
#include "step06_foam_sky/shaders/cascades.glsl"
// water.glsl: its Fresnel, and u_seabed_depth (metres from the mean level down to the seabed)
#include "water.glsl"

uniform vec2 u_grid_origin;  // metres: the first ray's rest position (x z), from the sea's origin
uniform float u_grid_step;   // metres between rays
uniform vec3 u_sun_in_air;   // the sun's light, travelling (down)

layout(location = 0) out vec4 out_ray;          // xy: where it crossed the level plane, zw: where it landed
layout(location = 1) out vec4 out_transmitted;  // r: the share of its light the surface let through

void main() {
    vec2 rest = u_grid_origin + u_grid_step * floor(gl_FragCoord.xy);
    vec4 displacement, slopes;
    surface_at(rest, 2.0 * u_grid_step, displacement, slopes);  // no wave the grid cannot carry
    vec3 n = choppy_normal(displacement, slopes);
    vec3 at = vec3(rest.x + displacement.x, displacement.y, rest.y + displacement.z);
    vec3 ray = refract(u_sun_in_air, n, 1.0 / WATER_INDEX);
    vec3 landed = at + ray * ((at.y + u_seabed_depth) / max(-ray.y, 1e-3));
    // The sun's rays are parallel: where they cross the level plane y = 0 they are spread evenly,
    // so the light a cell of rays carries is its area there (traced back from the surface along
    // the sun: the displaced, tilted surface catches what that area lets through).
    vec2 source = at.xz - u_sun_in_air.xz * (at.y / u_sun_in_air.y);
    out_ray = vec4(source, landed.xz);
    // What the surface lets in: a ray reflects the same share either way across it (Stokes), so
    // from the air at the sun's angle it is water.glsl's Fresnel from below at the refracted one.
    out_transmitted = vec4(1.0 - fresnel_from_water(max(-dot(ray, n), 0.0)), 0.0, 0.0, 1.0);
}
