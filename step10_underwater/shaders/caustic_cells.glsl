// Caustics: a cell is the square between four neighbouring rays, (i, j) to (i + 1, j + 1), cut
// into two triangles. The light a triangle carries is its area where the rays crossed the level
// plane (times what the surface let through); on the seabed it covers the triangle the rays land
// on, so the irradiance there over a flat sea's is the ratio of the two areas: the Jacobian of the
// map from where the light came to where it lands.
//
// A triangle that lands smaller than a texel cannot be drawn as one: it covers a texel's centre
// only now and then, and where the waves focus the light, thinner than the rasterizer's grid, it
// covers none and its light is lost (a lens's focus is exactly where every triangle shrinks). So
// each cell is drawn one of two ways, chosen the same in both passes: as its two triangles
// (caustics.vert/.frag) when both land at least half a texel wide in area, else as one point
// that puts the cell's whole light on the four texels around where it lands, shared bilinearly
// (caustic_points.vert/.frag): every ray's light reaches the floor.
#include "step10_underwater/underwater_units.h"

// caustic_rays.frag's, a texel a ray: xy where it crossed the level plane, zw where it landed;
layout(binding = UNIT_CAUSTIC_RAYS) uniform sampler2D u_rays;
layout(binding = UNIT_CAUSTIC_TRANSMITTED) uniform sampler2D u_transmitted;  // r: the share the surface let through
uniform int u_grid_side;          // rays along each side
uniform vec2 u_caustic_centre;    // metres: the window of seabed the texture covers
uniform float u_caustic_size;
uniform float u_texel_area;       // square metres: one texel of the caustic texture

struct Ray {
    vec2 source;
    vec2 landed;
    float transmitted;
};

Ray ray_at(int i, int j) {
    ivec2 at = ivec2(i, j);
    vec4 r = texelFetch(u_rays, at, 0);
    return Ray(r.xy, r.zw, texelFetch(u_transmitted, at, 0).r);
}

float triangle_area(vec2 a, vec2 b, vec2 c) {
    vec2 u = b - a, v = c - a;
    return 0.5 * abs(u.x * v.y - u.y * v.x);
}

// Cell (i, j): drawn as triangles, or as a point with the light it carries over a flat sea's.
struct Cell {
    bool as_triangles;
    vec2 centre;   // where it lands, on average (metres)
    float light;   // its source area times its mean transmittance (square metres)
};

Cell cell_at(int i, int j) {
    Ray a = ray_at(i, j), b = ray_at(i + 1, j), c = ray_at(i, j + 1), d = ray_at(i + 1, j + 1);
    float smaller = min(triangle_area(a.landed, b.landed, c.landed), triangle_area(b.landed, d.landed, c.landed));
    float source = triangle_area(a.source, b.source, c.source) + triangle_area(b.source, d.source, c.source);
    float transmitted = 0.25 * (a.transmitted + b.transmitted + c.transmitted + d.transmitted);
    return Cell(smaller >= 0.5 * u_texel_area, 0.25 * (a.landed + b.landed + c.landed + d.landed), source * transmitted);
}

// A point on the seabed in the texture's clip space.
vec4 seabed_clip(vec2 xz) { return vec4((xz - u_caustic_centre) / (0.5 * u_caustic_size), 0.0, 1.0); }
