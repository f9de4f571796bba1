#version 450 core
// Evaluates step06's shading.glsl at given normals, view and sun directions, for the read-back test
// against shading.hpp (MICROFACET is set by the test, one program per distribution).
layout(local_size_x = 64) in;
#include "step06_foam_sky/shaders/shading.glsl"

struct Sample {
    vec4 normal_alpha;   // n, alpha
    vec4 view_height;    // v, height (scaled)
    vec4 sun_bubbles;    // l, bubbles
    vec4 roughness;      // along, across, wind heading (x, z)
};
layout(std430, binding = 0) readonly buffer Inputs { Sample samples[]; };
// Per sample: (Schlick at n.v, isotropic Lambda(n.v) and D(n.h) at alpha = along, specular per unit
// sun), (scatter rgb, anisotropic D(h)), (anisotropic Lambda(v), Lambda(l), 0, 0).
layout(std430, binding = 1) writeonly buffer Outputs { vec4 results[]; };

uniform int u_count;
uniform vec4 u_k;  // k1 .. k4
uniform vec3 u_scatter_colour, u_bubble_colour, u_crest_colour, u_sun;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    vec3 n = samples[i].normal_alpha.xyz, v = samples[i].view_height.xyz, l = samples[i].sun_bubbles.xyz;
    float alpha = samples[i].normal_alpha.w;
    Roughness r = wind_roughness(n, samples[i].roughness.x, samples[i].roughness.y, samples[i].roughness.zw);
    vec3 h = normalize(v + l);
    ScatterSettings s = ScatterSettings(u_k.x, u_k.y, u_k.z, u_k.w, u_scatter_colour, u_bubble_colour, u_crest_colour);
    results[3 * i] = vec4(fresnel_schlick(dot(n, v), 0.02), smith_lambda(dot(n, v), alpha),
                          microfacet_distribution(max(dot(n, h), 0.0), alpha),
                          specular_term(n, v, l, r, 0.02, vec3(1.0)).x);
    results[3 * i + 1] = vec4(scatter_term(n, v, l, samples[i].view_height.w, r, samples[i].sun_bubbles.w, s, u_sun),
                              anisotropic_distribution(n, h, r));
    results[3 * i + 2] = vec4(anisotropic_lambda(n, v, r), anisotropic_lambda(n, l, r), 0.0, 0.0);
}
