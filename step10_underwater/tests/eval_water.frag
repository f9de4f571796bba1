#version 450 core
// water.glsl's functions evaluated on the GPU, a texel a case (tests/gpu_water.cpp): row 0,
// fresnel_from_water over cos_i in (0, 1); row 1, what an eye sees looking along a direction
// (the water's own light over a path, inscatter); row 2, the seabed's radiance.
#include "step10_underwater/shaders/water.glsl"

uniform int u_columns;
out vec4 out_value;

// The case of column i, as gpu_water.cpp computes it: an eye 0 to 20 m down, a direction from
// straight down to 60 degrees above the horizontal around the compass, a path 0.5 to 40 m.
void eye_case(int i, out float depth, out vec3 d, out float t) {
    float f = (float(i) + 0.5) / float(u_columns);
    depth = 20.0 * f;
    float elevation = radians(-90.0 + 150.0 * fract(7.0 * f)), azimuth = radians(360.0 * fract(13.0 * f));
    d = vec3(cos(elevation) * cos(azimuth), sin(elevation), cos(elevation) * sin(azimuth));
    t = 0.5 + 39.5 * fract(3.0 * f);
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float f = (float(texel.x) + 0.5) / float(u_columns);
    if (texel.y == 0) {
        out_value = vec4(fresnel_from_water(f), 0.0, 0.0, 1.0);
    } else if (texel.y == 1) {
        float depth, t;
        vec3 d;
        eye_case(texel.x, depth, d, t);
        out_value = vec4(inscatter(depth, d, t), 1.0);
    } else {
        out_value = vec4(seabed_radiance(4.0 * f), 1.0);  // caustics from dark to four times a flat sea's
    }
}
