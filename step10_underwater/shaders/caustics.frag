#version 450 core
// Caustics, a triangle of rays on the seabed: the irradiance it brings, relative to a flat sea's,
// is the ratio of its area where the light came from to its area where it landed (read from the
// screen-space derivatives of both), times the light the surface let through, over a flat
// surface's. The triangles add up (blending ONE, ONE), so where the map folds, every layer's light
// counts.
in vec2 v_source;
in vec2 v_landed;
in float v_transmitted;
flat in int v_cell_drawn;
uniform float u_flat_transmitted;  // what a level surface lets through of the sun's light
out vec4 out_irradiance;

void main() {
    if (v_cell_drawn == 0) discard;  // a cell drawn as a point (caustic_points.vert)
    float source_area = abs(dFdx(v_source).x * dFdy(v_source).y - dFdx(v_source).y * dFdy(v_source).x);
    float landed_area = abs(dFdx(v_landed).x * dFdy(v_landed).y - dFdx(v_landed).y * dFdy(v_landed).x);
    out_irradiance = vec4(source_area / landed_area * v_transmitted / u_flat_transmitted, 0.0, 0.0, 1.0);
}
