#version 450 core
// Caustics as a lens makes them: a grid of the sun's rays, one per vertex, each refracted where it
// meets the moving surface (step06's cascades, read as its mesh reads them) and carried straight
// down to the seabed. The triangles between neighbouring rays are drawn where the rays land, so
// that light the waves focus lands on a small triangle, light they spread on a large one.
#include "step06_foam_sky/shaders/cascades.glsl"

uniform vec2 u_grid_origin;   // metres: the first ray's rest position (x z), from the sea's origin
uniform float u_grid_step;    // metres between rays
uniform int u_grid_side;      // rays along each side
uniform vec3 u_sun_in_air;    // the sun's light, travelling (down)
uniform float u_seabed_depth;
uniform vec2 u_caustic_centre;
uniform float u_caustic_size;

out vec2 v_source;    // where the ray crossed a level plane above the waves, and
out vec2 v_landed;    // where it reached the seabed (metres)
out float v_transmitted;  // the fraction of its light the surface let through

const float WATER_INDEX = 1.333;

float fresnel_into_water(float cos_i) {
    float sin_t2 = (1.0 - cos_i * cos_i) / (WATER_INDEX * WATER_INDEX);
    float cos_t = sqrt(1.0 - sin_t2);
    float rs = (cos_i - WATER_INDEX * cos_t) / (cos_i + WATER_INDEX * cos_t);
    float rp = (WATER_INDEX * cos_i - cos_t) / (WATER_INDEX * cos_i + cos_t);
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

void main() {
    int i = gl_VertexID % u_grid_side, j = gl_VertexID / u_grid_side;
    vec2 rest = u_grid_origin + u_grid_step * vec2(i, j);
    vec4 displacement, slopes;
    surface_at(rest, 2.0 * u_grid_step, displacement, slopes);  // no wave the grid cannot carry
    vec3 n = choppy_normal(displacement, slopes);
    vec3 at = vec3(rest.x + displacement.x, displacement.y, rest.y + displacement.z);
    vec3 ray = refract(u_sun_in_air, n, 1.0 / WATER_INDEX);
    float down = max(-ray.y, 1e-3);
    vec3 landed = at + ray * ((at.y + u_seabed_depth) / down);
    // The sun's rays are parallel: where they cross the level plane y = 0 they are spread evenly, so
    // the light a triangle of rays carries is its area there (traced back from the surface along
    // the sun: the displaced, tilted surface catches what that area lets through).
    v_source = at.xz - u_sun_in_air.xz * (at.y / u_sun_in_air.y);
    v_landed = landed.xz;
    v_transmitted = fresnel_into_water(max(dot(-u_sun_in_air, n), 0.0));
    gl_Position = vec4((landed.xz - u_caustic_centre) / (0.5 * u_caustic_size), 0.0, 1.0);
}
