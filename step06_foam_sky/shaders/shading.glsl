// Chapter 5.2 and 5.6: light on water that is not opaque (shading.hpp is the CPU reference).
//   colour = (1 - F) (ambient + scatter) + F sky(R) + specular
// F: Schlick's Fresnel with F0 = 0.02 (water, n = 1.33) at the viewing angle; R = 2N(N.V) - V;
// specular: a microfacet BRDF, GGX or Beckmann, with Smith's height-correlated masking;
// scatter: the notes' subsurface terms (Acerola's, their k1 .. k4): light through the crests
// (scatter_crest, needs the height H), towards the viewer (scatter_view), Lambert (scatter_lambert),
// and bubbles (scatter_bubbles).
#ifndef MICROFACET
#define MICROFACET 0  // 0: GGX, 1: Beckmann
#endif

const float PI = 3.14159265358979;

float fresnel_schlick(float cos_theta, float f0) {
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);
}

// Smith's Lambda for a direction at cos_theta from the normal, roughness alpha.
float smith_lambda(float cos_theta, float alpha) {
    float c = clamp(cos_theta, 1e-4, 1.0);
    float tan2 = (1.0 - c * c) / (c * c);
#if MICROFACET == 0
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * tan2));
#else
    float a = 1.0 / (alpha * sqrt(tan2) + 1e-6);  // Walter et al.'s rational fit
    return a < 1.6 ? (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a) : 0.0;
#endif
}

// D(h): how many microfacets face h, per steradian, for a surface of roughness alpha (the slopes'
// spread). Normalised: its integral against (N.H) over the hemisphere is 1, so a rougher sea spreads
// the same sunlight wider instead of making more of it.
float ggx_distribution(float n_dot_h, float alpha) {
    float c2 = n_dot_h * n_dot_h, a2 = alpha * alpha;
    float d = c2 * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

float beckmann_distribution(float n_dot_h, float alpha) {
    float c2 = n_dot_h * n_dot_h, a2 = alpha * alpha;
    return exp((c2 - 1.0) / (a2 * c2)) / (PI * a2 * c2 * c2);
}

float microfacet_distribution(float n_dot_h, float alpha) {
#if MICROFACET == 0
    return ggx_distribution(n_dot_h, alpha);
#else
    return beckmann_distribution(n_dot_h, alpha);
#endif
}

// Radiance reflected towards V by the sun (radiance-weighted by N.L already).
vec3 specular_term(vec3 n, vec3 v, vec3 l, float alpha, float f0, vec3 sun) {
    float n_dot_l = dot(n, l), n_dot_v = dot(n, v);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    float d = microfacet_distribution(max(dot(n, h), 0.0), alpha);
    float g = 1.0 / (1.0 + smith_lambda(n_dot_v, alpha) + smith_lambda(n_dot_l, alpha));
    float f = fresnel_schlick(dot(v, h), f0);
    return sun * d * g * f / (4.0 * n_dot_v);
}

struct ScatterSettings {
    float scatter_crest, scatter_view, scatter_lambert, scatter_bubbles;  // the notes' k1 .. k4
    vec3 scatter_colour, bubble_colour;
    vec3 crest_colour;  // sunlight through a thin crest: brighter and greener than the deep water
};

// height: metres above the mean level, scaled to about [0, 1] by the caller.
vec3 scatter_term(vec3 n, vec3 v, vec3 l, float height, float alpha, float bubbles, ScatterSettings s, vec3 sun) {
    float crest = s.scatter_crest * clamp(height, 0.0, 1.0) * pow(max(dot(l, -v), 0.0), 4.0) * pow(0.5 - 0.5 * dot(l, n), 3.0);
    float towards_viewer = s.scatter_view * pow(max(dot(v, n), 0.0), 2.0);
    vec3 scatter = (crest * s.crest_colour + towards_viewer * s.scatter_colour) * sun / (1.0 + smith_lambda(dot(n, l), alpha));
    scatter += s.scatter_lambert * max(dot(l, n), 0.0) * s.scatter_colour * sun + s.scatter_bubbles * bubbles * s.bubble_colour * sun;
    return scatter;
}
