// Reading the cascades combined around the camera (combined_surface.hpp says how the levels are
// laid out): for a point, the finest level that holds it, and the next one's weight in the band
// where the first hands over; a point's coordinates in a level; the mip level of a footprint.
// Compiled in only where COMBINED_SURFACE is 1 (the setting surface=combined).
#ifndef COMBINED_SURFACE
#define COMBINED_SURFACE 0
#endif
#if COMBINED_SURFACE
#include "step06_foam_sky/texture_units.h"

const int MAX_COMBINED_LEVELS = 12;
const float LEVEL_REACH = 0.4, BLEND_FROM = 0.3;  // combined_surface.hpp's kLevelReach, kBlendFrom
layout(binding = UNIT_COMBINED_DISPLACEMENT) uniform sampler2DArray u_combined_displacement;
layout(binding = UNIT_COMBINED_SLOPES) uniform sampler2DArray u_combined_slopes;
uniform int u_combined_levels;
uniform int u_combined_cascades;     // the levels hold cascades 0 .. this - 1; the rest are read as before
uniform int u_combined_n;            // texels per side of a level
uniform float u_combined_side0;      // metres: level 0's side; level k's is 2^k times it
uniform vec2 u_combined_centre;      // the camera (x, z), which every level is centred on to a texel
uniform vec2 u_combined_corner[MAX_COMBINED_LEVELS];  // each level's first cell's corner

struct CombinedLevels {
    int level;          // the finest level that holds the point
    float next_weight;  // how much of level + 1 to blend in (0 inside, 1 at LEVEL_REACH)
};

// combined_surface.hpp's combined_level_at: the square's distance from the camera decides.
CombinedLevels combined_levels_at(vec2 p) {
    vec2 offset = abs(p - u_combined_centre);
    float reach = max(offset.x, offset.y);
    int level = clamp(int(ceil(log2(max(reach / (LEVEL_REACH * u_combined_side0), 1.0)))), 0, u_combined_levels - 1);
    float side = u_combined_side0 * exp2(float(level));
    float next = level + 1 < u_combined_levels ? clamp((reach / side - BLEND_FROM) / (LEVEL_REACH - BLEND_FROM), 0.0, 1.0) : 0.0;
    return CombinedLevels(level, next);
}

float combined_texel(int level) { return u_combined_side0 * exp2(float(level)) / float(u_combined_n); }

vec3 combined_uv(vec2 p, int level) {
    return vec3((p - u_combined_corner[level]) / (u_combined_side0 * exp2(float(level))), float(level));
}

// The mip level of `level` that averages a footprint `footprint` metres wide (below 0: magnified).
float combined_lod(int level, float footprint) { return log2(footprint / combined_texel(level)); }

// (l Dx, h, l Dz, l dDx/dz) of the combined cascades as a sample `footprint` metres wide sees it
// (the mesh's vertices: ocean.tese). textureLod, per point: no neighbour is needed.
vec4 combined_displacement_at(vec2 p, float footprint) {
    CombinedLevels at = combined_levels_at(p);
    vec4 d = textureLod(u_combined_displacement, combined_uv(p, at.level), combined_lod(at.level, footprint));
    if (at.next_weight > 0.0) {
        int next = at.level + 1;
        d = mix(d, textureLod(u_combined_displacement, combined_uv(p, next), combined_lod(next, footprint)), at.next_weight);
    }
    return d;
}
#endif
