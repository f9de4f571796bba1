#version 450 core
// The plot, one pixel at a time: for each curve y = f(x) the pixel's distance to it is
// |dy| / sqrt(1 + m^2), dy = y - f(x) in pixels and m = f'(x) turned into pixels per pixel (the
// axes' metres per pixel differ), which keeps lines the same width on steep slopes.
#include "sine_sum.glsl"
#include "digits.glsl"

in vec2 v_uv;
out vec4 out_color;

uniform vec2 u_resolution;     // pixels
uniform vec2 u_x_range;        // metres at the left and right edges
uniform float u_y_extent;      // metres from the axis to the top edge
uniform bool u_show_waves;
uniform bool u_show_sum;
uniform bool u_show_curvature;
uniform float u_line_width;    // pixels
uniform vec3 u_wave_colors[MAX_WAVES];

// 1 on the curve, fading to 0 across the pixel at the line's edge (half the width from the curve).
float line(float value, float curve, float slope, vec2 metres_per_pixel, float width) {
    float dy = (value - curve) / metres_per_pixel.y;
    float pixel_slope = slope * metres_per_pixel.x / metres_per_pixel.y;
    float distance = abs(dy) / sqrt(1.0 + pixel_slope * pixel_slope);
    return clamp(0.5 * width + 0.5 - distance, 0.0, 1.0);
}

// Thin lines along one axis at a round spacing (1, 10, 100 ... or 0.1 ...) giving 4 to 40 lines.
float grid(float coordinate, float span, float metres_per_pixel) {
    float spacing = grid_spacing(span);
    float d = abs(fract(coordinate / spacing + 0.5) - 0.5) * spacing / metres_per_pixel;
    return clamp(1.0 - d, 0.0, 1.0);
}

void main() {
    vec2 metres_per_pixel = vec2(u_x_range.y - u_x_range.x, 2.0 * u_y_extent) / u_resolution;
    float x = mix(u_x_range.x, u_x_range.y, v_uv.x);
    float y = mix(-u_y_extent, u_y_extent, v_uv.y);

    vec3 color = vec3(0.06, 0.07, 0.09);
    float minor = max(grid(x, u_x_range.y - u_x_range.x, metres_per_pixel.x),
                      grid(y, 2.0 * u_y_extent, metres_per_pixel.y));
    color = mix(color, vec3(0.13, 0.15, 0.18), minor);
    float axes = max(clamp(1.0 - abs(x) / metres_per_pixel.x, 0.0, 1.0),
                     clamp(1.0 - abs(y) / metres_per_pixel.y, 0.0, 1.0));
    color = mix(color, vec3(0.45, 0.48, 0.52), axes);

    // Axis numbers, in metres: x along the bottom edge, y along the left one, at round steps.
    vec2 pixel = gl_FragCoord.xy;
    float x_step = label_step(u_x_range.y - u_x_range.x), y_step = label_step(2.0 * u_y_extent);
    float x_label = floor(x / x_step + 0.5) * x_step, y_label = floor(y / y_step + 0.5) * y_step;
    vec2 x_centre = vec2((x_label - u_x_range.x) / metres_per_pixel.x, 12.0);
    vec2 y_centre = vec2(26.0, (y_label + u_y_extent) / metres_per_pixel.y);
    float numbers = 0.0;
    // (not under the y numbers, and whole: none cut by an edge)
    if (x_centre.x > 56.0 && x_centre.x < u_resolution.x - 16.0) numbers = number_coverage(x_label, decimals_for(x_step), pixel, x_centre, vec2(6.0, 10.0));
    if (y_centre.y > 28.0 && y_centre.y < u_resolution.y - 10.0) numbers = max(numbers, number_coverage(y_label, decimals_for(y_step), pixel, y_centre, vec2(6.0, 10.0)));
    color = mix(color, vec3(0.62, 0.66, 0.72), numbers);

    if (u_show_waves) {
        for (int i = 0; i < u_wave_count; ++i) {
            float c = line(y, wave_height(i, x), wave_slope(i, x), metres_per_pixel, u_line_width);
            color = mix(color, u_wave_colors[i], 0.85 * c);
        }
    }
    if (u_show_sum) {
        float c = line(y, sum_of_sines(x), sum_of_sines_slope(x), metres_per_pixel, 2.0 * u_line_width);
        color = mix(color, vec3(0.95, 0.97, 1.0), c);
    }
    if (u_show_curvature) {
        // The sum's curvature (1/m, on the same axis), in pink; its own slope, by a difference one
        // pixel wide, keeps the line's width.
        float h = metres_per_pixel.x;
        float curvature = sum_of_sines_curvature(x);
        float turn = (sum_of_sines_curvature(x + h) - sum_of_sines_curvature(x - h)) / (2.0 * h);
        float c = line(y, curvature, turn, metres_per_pixel, u_line_width);
        color = mix(color, vec3(1.0, 0.3, 0.45), c);
    }
    out_color = vec4(color, 1.0);
}
