// The fog's colour (fog.glsl takes it): the sky at the horizon, blurred, in the azimuth the eye
// looks. It depends on the azimuth alone, so Sky::render tabulates it once a frame
// (sky_horizon.frag, HORIZON_TEXELS around the horizon, one row of a 2D texture: ES has no 1D
// textures) and a pixel reads two texels of the table instead of a trilinear fetch from the cube
// (that fetch was 4 % of the ocean pass on llvmpipe, docs/performance.md). sky.hpp's
// horizon_coordinate is the CPU reference.
#include "step06_foam_sky/texture_units.h"

const int HORIZON_TEXELS = 256;
layout(binding = UNIT_SKY_HORIZON) uniform sampler2D u_sky_horizon;  // one row; linear, repeating along it

// Where the horizontal direction (x, z) falls in the table, in [0, 1) up to a whole turn: the
// "diamond angle", a stand-in for azimuth / 2 pi that needs no atan. It runs around the square
// |x| + |z| = 1, a quarter per side: (1, 0) is 0, (0, 1) 1/4, (-1, 0) 1/2, (0, -1) 3/4; it grows
// with the azimuth, so the table samples the horizon in order.
float horizon_coordinate(vec2 d) {
    float s = d.y / max(abs(d.x) + abs(d.y), 1e-20);  // in [-1, 1]
    return 0.25 * (d.x >= 0.0 ? s : 2.0 - s);  // below 0 on the side towards (0, -1): the table repeats
}

// The horizontal direction (x, z) at coordinate u in [0, 1): horizon_coordinate's inverse, on the
// square (normalise it to use it).
vec2 horizon_direction(float u) {
    float a = 4.0 * u;
    if (a < 1.0) return vec2(1.0 - a, a);
    if (a < 2.0) return vec2(1.0 - a, 2.0 - a);
    if (a < 3.0) return vec2(a - 3.0, 2.0 - a);
    return vec2(a - 3.0, a - 4.0);
}

// The fog's colour along `direction` (any length; only its azimuth counts).
vec3 horizon_colour(vec3 direction) {
    return textureLod(u_sky_horizon, vec2(horizon_coordinate(direction.xz), 0.5), 0.0).rgb;
}
