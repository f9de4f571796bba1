#version 450 core
// A cell's light on the four texels around where it lands, shared as bilinear filtering shares a
// texel among the four around it: each texel's weight falls off with its distance from the point
// (gl_PointCoord: 0 to 1 across the point's two texels), and the four weights add to one.
in float v_irradiance;
out vec4 out_irradiance;

void main() {
    vec2 from_centre = abs(gl_PointCoord * 2.0 - 1.0);  // in texels
    vec2 weight = max(1.0 - from_centre, 0.0);
    out_irradiance = vec4(v_irradiance * weight.x * weight.y, 0.0, 0.0, 1.0);
}
