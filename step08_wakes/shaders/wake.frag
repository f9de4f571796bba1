#version 450 core
// The wake seen from above: the wave field's heights (one float a cell, uploaded each frame)
// read bilinearly, lit by a low sun and a pale sky, with the boat's waterline drawn over them.
// wave_field.cpp's height_at is the CPU reference for the bilinear read.
in vec2 v_uv;
out vec4 out_colour;

layout(binding = 0) uniform highp sampler2D u_heights;  // n x n, texel (i, j) at cell (i, j)
uniform int u_cells;             // n
uniform float u_cell;            // metres
uniform vec2 u_first_cell;       // cell (0, 0)'s centre, metres from the view's centre (x, z)
uniform vec2 u_half_view;        // metres from the view's centre to its right and top edges
uniform float u_pixels_high;     // the picture's height in pixels
uniform vec2 u_boat;             // the boat's middle, from the view's centre
uniform vec2 u_heading;          // unit, (x, z)
uniform float u_boat_length;     // metres
uniform float u_show_field;      // 1: the grid's edge and absorbing layer are outlined
uniform float u_absorbing_width; // metres
uniform float u_kelvin;          // 1: Kelvin's edges drawn either side of the track behind
uniform float u_kelvin_angle;    // their half-angle, radians (kelvin.cpp; deep water: arcsin(1/3))
uniform float u_relief;          // how many times the slopes are exaggerated in the shading

// The height at a point (x, z) from the view's centre: 0 outside the grid, as height_at.
float height_at(vec2 p) {
    vec2 u = (p - u_first_cell) / u_cell;
    if (u.x < 0.0 || u.y < 0.0 || u.x >= float(u_cells - 1) || u.y >= float(u_cells - 1)) return 0.0;
    ivec2 i = ivec2(floor(u));
    vec2 f = u - vec2(i);
    float h00 = texelFetch(u_heights, i, 0).r, h10 = texelFetch(u_heights, i + ivec2(1, 0), 0).r;
    float h01 = texelFetch(u_heights, i + ivec2(0, 1), 0).r, h11 = texelFetch(u_heights, i + ivec2(1, 1), 0).r;
    return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

void main() {
    vec2 p = (2.0 * v_uv - 1.0) * u_half_view;  // metres from the view's centre; z up the screen
    float h = u_cell;
    vec2 slope = vec2(height_at(p + vec2(h, 0.0)) - height_at(p - vec2(h, 0.0)),
                      height_at(p + vec2(0.0, h)) - height_at(p - vec2(0.0, h))) / (2.0 * h);
    // Shaded as a map shades its hills: the slopes exaggerated u_relief times (a wake's waves are
    // a few centimetres high over metres: seen from straight above at their true slope they would
    // hardly show), lit by a low sun in the south-west, and the sky reflected by the faces that
    // tilt towards it.
    vec3 n = normalize(vec3(-u_relief * slope.x, 1.0, -u_relief * slope.y));
    vec3 sun = normalize(vec3(-0.6, 0.5, -0.62));
    float lit = max(dot(n, sun), 0.0);
    float flat_lit = sun.y;
    vec3 water = vec3(0.02, 0.11, 0.17);
    vec3 sky = vec3(0.62, 0.75, 0.86);
    float towards_sky = clamp(0.5 + 2.0 * (lit - flat_lit), 0.0, 1.0);
    vec3 colour = water * (0.55 + 0.9 * lit) + 0.25 * sky * towards_sky * towards_sky;
    // The grid's edge and its absorbing layer, faintly (the field is 0 beyond the edge).
    vec2 from_centre = abs(p - (u_first_cell + 0.5 * float(u_cells - 1) * u_cell));
    float half_side = 0.5 * float(u_cells) * u_cell;
    float to_edge = half_side - max(from_centre.x, from_centre.y);
    if (u_show_field > 0.5) {
        if (to_edge < 0.0) colour *= 0.7;
        else if (to_edge < u_absorbing_width) colour = mix(colour, vec3(0.2, 0.1, 0.05), 0.12);
    }
    vec2 d = p - u_boat;
    vec2 local = vec2(dot(d, u_heading), dot(d, vec2(-u_heading.y, u_heading.x)));  // along, across
    // Kelvin's edges: where |across| = -along tan(angle), a line about a pixel wide.
    if (u_kelvin > 0.5 && local.x < 0.0) {
        float miss = abs(abs(local.y) * cos(u_kelvin_angle) + local.x * sin(u_kelvin_angle));  // distance to the line
        float pixel = 2.0 * u_half_view.y / u_pixels_high;
        colour = mix(colour, vec3(1.0, 0.8, 0.3), 0.8 * (1.0 - smoothstep(0.5 * pixel, 1.5 * pixel, miss)));
    }
    // The boat's waterline: an ellipse L long and L / 3 wide, white with a dark rim.
    float r = length(local / vec2(0.5 * u_boat_length, u_boat_length / 6.0));
    if (r < 1.0) colour = r < 0.8 ? vec3(0.92, 0.9, 0.86) : vec3(0.25, 0.08, 0.05);
    out_colour = vec4(colour, 1.0);
}
