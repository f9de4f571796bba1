#version 450 core
// Each triangle of rays brings the light that crossed its area of the sun's beam onto the area it
// covers on the seabed: the irradiance there, relative to a flat sea's, is the ratio of the two
// areas (the Jacobian of the map from the beam to the landing point, read from the screen-space
// derivatives of both) times the light the surface let through, over a flat surface's. The
// triangles add up (blending ONE, ONE), so where the map folds, every layer's light counts.
in vec2 v_source;
in vec2 v_landed;
in float v_transmitted;
uniform float u_flat_transmitted;  // what a level surface lets through of the sun's light
out vec4 out_irradiance;

void main() {
    float source_area = abs(dFdx(v_source).x * dFdy(v_source).y - dFdx(v_source).y * dFdy(v_source).x);
    float landed_area = abs(dFdx(v_landed).x * dFdy(v_landed).y - dFdx(v_landed).y * dFdy(v_landed).x);
    float ratio = source_area / max(landed_area, 1e-3 * source_area);
    out_irradiance = vec4(ratio * v_transmitted / u_flat_transmitted, 0.0, 0.0, 1.0);
}
