#version 450 core
// The debug view of one map: the chosen channel over the screen (one tile, 1:1 aspect), blue for
// negative, white at zero, red for positive, scaled by u_range. The Jacobian has a scale of its
// own, whatever u_range: white at J = 1 (untouched), red as the surface squeezes towards J = 0,
// blue as it stretches towards J = 2, and black where J < 0 (the surface folds: a breaking crest).
// The spectrum view shows log10 of each mode's energy.
// Right of the tile, a legend: the colour bar with the values at its ends and middle.
#include "ocean_maps.glsl"
#include "srgb.glsl"
#include "digits.glsl"

in vec2 v_uv;
out vec4 out_color;

uniform int u_map;           // MAP_* below
uniform float u_range;       // value shown at full colour
uniform vec2 u_resolution;   // pixels
uniform sampler2D u_spectrum_image;  // log10 energy, already coloured (RGBA8)
uniform int u_layer;                 // the cascade (0: step05 runs one)

const int MAP_HEIGHT = 0, MAP_DISPLACEMENT_X = 1, MAP_DISPLACEMENT_Z = 2, MAP_SLOPE_X = 3, MAP_SLOPE_Z = 4,
          MAP_JACOBIAN = 5, MAP_SPECTRUM = 6;

vec3 diverging(float v) {
    v = clamp(v, -1.0, 1.0);
    return v < 0.0 ? mix(vec3(1.0), vec3(0.1, 0.3, 0.9), -v) : mix(vec3(1.0), vec3(0.85, 0.15, 0.1), v);
}

// J's colours: squeezed (J < 1) red, stretched blue, folded (J < 0) black, a colour no other J has.
vec3 jacobian_colour(float j) { return j < 0.0 ? vec3(0.0) : diverging(1.0 - j); }

// The legend (sRGB) beside a tile whose right edge is at x = right (pixels): a bar from -u_range (bottom)
// to +u_range (top) in the map's colours, numbered at both ends and the middle (the Jacobian's
// from J = 0 to 2, with the folded J < 0 colour in a swatch below it). Nothing where the margin is
// too narrow.
vec3 legend(vec2 pixel, float right, float side) {
    vec3 background = vec3(0.06, 0.07, 0.09);  // the margin's colour (sRGB, as written out)
    if (u_map == MAP_SPECTRUM || u_resolution.x - right < 90.0) return background;
    float bottom = 0.5 * (u_resolution.y - side) + 0.1 * side, height = 0.8 * side;
    bool jacobian_map = u_map == MAP_JACOBIAN;
    vec2 bar = pixel - vec2(right + 18.0, bottom);
    if (bar.x >= 0.0 && bar.x < 14.0 && bar.y >= 0.0 && bar.y < height) {
        float v = 2.0 * bar.y / height - 1.0;
        return linear_to_srgb(jacobian_map ? jacobian_colour(1.0 + v) : diverging(v));
    }
    if (jacobian_map && bar.x >= 0.0 && bar.x < 14.0 && bar.y >= -0.07 * side && bar.y < -0.02 * side)
        return linear_to_srgb(jacobian_colour(-1.0));  // the folded colour, below J = 0
    float offset = jacobian_map ? 1.0 : 0.0, range = jacobian_map ? 1.0 : u_range;  // J: 0, 1, 2
    int decimals = range >= 10.0 ? 0 : range >= 1.0 ? 1 : range >= 0.1 ? 2 : 3;
    float numbers = 0.0;
    for (int i = -1; i <= 1; ++i) {
        vec2 centre = vec2(right + 64.0, bottom + 0.5 * height * (1.0 + float(i)));
        numbers = max(numbers, number_coverage(offset + float(i) * range, decimals, pixel, centre, vec2(6.0, 10.0)));
    }
    return mix(background, vec3(0.75), numbers);
}

void main() {
    // A square tile in the middle of the screen.
    float side = min(u_resolution.x, u_resolution.y);
    vec2 uv = (gl_FragCoord.xy - 0.5 * (u_resolution - side)) / side;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
        out_color = vec4(legend(gl_FragCoord.xy, 0.5 * (u_resolution.x + side), side), 1.0);
        return;
    }
    if (u_map == MAP_SPECTRUM) {
        out_color = texture(u_spectrum_image, uv);
        return;
    }
    vec4 displacement = textureLod(u_displacement, vec3(uv, float(u_layer)), 0.0);
    vec4 slopes = textureLod(u_slopes, vec3(uv, float(u_layer)), 0.0);
    float value = u_map == MAP_HEIGHT ? displacement.y
                : u_map == MAP_DISPLACEMENT_X ? displacement.x
                : u_map == MAP_DISPLACEMENT_Z ? displacement.z
                : u_map == MAP_SLOPE_X ? slopes.x
                : u_map == MAP_SLOPE_Z ? slopes.y
                : jacobian(displacement, slopes);
    vec3 colour = u_map == MAP_JACOBIAN ? jacobian_colour(value) : diverging(value / u_range);
    out_color = vec4(linear_to_srgb(colour), 1.0);
}
