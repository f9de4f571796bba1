#version 450 core
// The debug view of one map: the chosen channel over the screen (one tile, 1:1 aspect), blue for
// negative, white at zero, red for positive, scaled by u_range. The Jacobian is drawn around 1
// (red where J < 0: the surface folds). The spectrum view shows log10 of each mode's energy.
#include "ocean_maps.glsl"
#include "srgb.glsl"

in vec2 v_uv;
out vec4 out_color;

uniform int u_map;           // MAP_* below
uniform float u_range;       // value shown at full colour
uniform vec2 u_resolution;   // pixels
uniform sampler2D u_spectrum_image;  // log10 energy, already coloured (RGBA8)
uniform int u_layer;                 // the cascade (step06; 0 in step05)

const int MAP_HEIGHT = 0, MAP_DISPLACEMENT_X = 1, MAP_DISPLACEMENT_Z = 2, MAP_SLOPE_X = 3, MAP_SLOPE_Z = 4,
          MAP_JACOBIAN = 5, MAP_SPECTRUM = 6;

vec3 diverging(float v) {
    v = clamp(v, -1.0, 1.0);
    return v < 0.0 ? mix(vec3(1.0), vec3(0.1, 0.3, 0.9), -v) : mix(vec3(1.0), vec3(0.85, 0.15, 0.1), v);
}

void main() {
    // A square tile in the middle of the screen.
    float side = min(u_resolution.x, u_resolution.y);
    vec2 uv = (gl_FragCoord.xy - 0.5 * (u_resolution - side)) / side;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
        out_color = vec4(0.06, 0.07, 0.09, 1.0);
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
                : jacobian(displacement, slopes) - 1.0;
    vec3 colour = diverging(value / u_range);
    if (u_map == MAP_JACOBIAN && value < -1.0) colour = vec3(0.6, 0.0, 0.0);  // J < 0
    out_color = vec4(linear_to_srgb(colour), 1.0);
}
