// What an eye in the water sees along a ray that meets no surface: the seabed, lit through the
// caustics the waves focus on it, or the water itself to the end of sight.
#include "step10_underwater/underwater_units.h"
#include "water.glsl"

layout(binding = UNIT_CAUSTICS) uniform sampler2D u_caustics;  // r: irradiance relative to a flat sea's
uniform vec2 u_caustic_centre;  // the window of seabed the texture covers: its centre (metres, x z)
uniform float u_caustic_size;   // and its side
uniform bool u_show_caustics;
// A camera below the surface exposes for the water, which holds far less light than the sky: the
// light it records is scaled by this before step06's exposure (the sea above keeps its own).
uniform float u_below_exposure;

// The caustic texture at a point of the seabed, filtered bilinearly by hand (the texture is
// nearest-filtered in every profile); towards its window's edge it fades to 1, a flat sea's light,
// which is the pattern's mean: no seam where the window ends.
float caustic_at(vec2 xz) {
    if (!u_show_caustics) return 1.0;
    vec2 uv = (xz - u_caustic_centre) / u_caustic_size + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    vec2 to_edge = min(uv, 1.0 - uv);
    float inside = smoothstep(0.0, 0.15, min(to_edge.x, to_edge.y));
    ivec2 size = textureSize(u_caustics, 0);
    vec2 at = uv * vec2(size) - 0.5;
    ivec2 base = ivec2(floor(at));
    vec2 f = at - vec2(base);
    ivec2 top = size - 1;
    float a = texelFetch(u_caustics, clamp(base, ivec2(0), top), 0).r;
    float b = texelFetch(u_caustics, clamp(base + ivec2(1, 0), ivec2(0), top), 0).r;
    float c = texelFetch(u_caustics, clamp(base + ivec2(0, 1), ivec2(0), top), 0).r;
    float d = texelFetch(u_caustics, clamp(base + ivec2(1, 1), ivec2(0), top), 0).r;
    return mix(1.0, mix(mix(a, b, f.x), mix(c, d, f.x), f.y), inside);
}

// The radiance reaching `origin` (depth -origin.y) along -d from the direction d: the seabed where
// d meets it within max_t, else the water's own light over max_t (the surface's, if any, is the
// caller's to add, attenuated by exp(-c max_t)).
vec3 water_ray(vec3 origin, vec3 d, float max_t) {
    float depth = max(-origin.y, 0.0);
    if (d.y < -1e-4) {
        float t = (origin.y + u_seabed_depth) / -d.y;
        if (t < max_t) {
            vec3 bed = origin + t * d;
            return seabed_radiance(caustic_at(bed.xz)) * exp(-extinction() * t) + inscatter(depth, d, t);
        }
    }
    return inscatter(depth, d, max_t);
}
