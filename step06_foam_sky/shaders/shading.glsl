// Chapter 5.2 and 5.6: light on water that is not opaque (shading.hpp is the CPU reference).
//   colour = (1 - F) (ambient + scatter) + F sky(R) + specular
// F: Schlick's Fresnel with F0 = 0.02 (water, n = 1.33) at the viewing angle; R = 2N(N.V) - V;
// specular: a microfacet BRDF, GGX or Beckmann, anisotropic (rougher along the wind than across
// it, as Cox and Munk photographed), with Smith's height-correlated masking;
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

// The microfacets' roughness: alpha along the wind and across it, and the wind's frame on the
// plane the normal stands on (wind_roughness). The waves too short to draw tilt the water more
// along the wind than across it, so the sun's glitter is an ellipse stretched along the wind.
struct Roughness {
    float along, across;
    vec3 along_axis, across_axis;  // the wind projected on n's plane, and n x it: equal lengths
};

// The frame, made once a pixel (D and both Lambdas read it), for the wind's heading (x, z).
Roughness wind_roughness(vec3 n, float along, float across, vec2 wind) {
    vec3 axis = vec3(wind.x, 0.0, wind.y) - n * (n.x * wind.x + n.z * wind.y);
    return Roughness(along, across, axis, cross(n, axis));
}

Roughness isotropic(float alpha) { return Roughness(alpha, alpha, vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0)); }

// w's components along the wind and across it: the two axes have the same length, so the
// components keep w's azimuth without normalising anything (only their ratio is used).
vec2 wind_components(vec3 w, Roughness r) { return vec2(dot(w, r.along_axis), dot(w, r.across_axis)); }

// An anisotropic D is the isotropic one at the alpha of h's azimuth, 1/alpha^2 = cos^2/along^2 +
// sin^2/across^2, times alpha^2 / (along across) (its slopes' density is an ellipse, not a circle).
// Where h is n (no azimuth) D does not depend on that alpha.
float anisotropic_distribution(vec3 n, vec3 h, Roughness r) {
    vec2 p = wind_components(h, r), p2 = p * p;
    float length2 = p2.x + p2.y;
    float alpha2 = length2 > 1e-12 ? length2 / (p2.x / (r.along * r.along) + p2.y / (r.across * r.across)) : r.along * r.along;
    return microfacet_distribution(max(dot(n, h), 0.0), sqrt(alpha2)) * alpha2 / (r.along * r.across);
}

// Smith's Lambda of a direction w: the slopes it sees are the microfacets' slopes projected on its
// azimuth, of spread alpha^2 = cos^2 along^2 + sin^2 across^2.
float anisotropic_lambda(vec3 n, vec3 w, Roughness r) {
    vec2 p = wind_components(w, r), p2 = p * p;
    float length2 = p2.x + p2.y;
    float alpha2 = length2 > 1e-12 ? (p2.x * r.along * r.along + p2.y * r.across * r.across) / length2 : r.along * r.along;
    return smith_lambda(dot(n, w), sqrt(alpha2));
}

// Radiance reflected towards V by the sun (radiance-weighted by N.L already).
vec3 specular_term(vec3 n, vec3 v, vec3 l, Roughness r, float f0, vec3 sun) {
    float n_dot_l = dot(n, l), n_dot_v = dot(n, v);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    float d = anisotropic_distribution(n, h, r);
    float g = 1.0 / (1.0 + anisotropic_lambda(n, v, r) + anisotropic_lambda(n, l, r));
    float f = fresnel_schlick(dot(v, h), f0);
    return sun * d * g * f / (4.0 * n_dot_v);
}

struct ScatterSettings {
    float scatter_crest, scatter_view, scatter_lambert, scatter_bubbles;  // the notes' k1 .. k4
    vec3 scatter_colour, bubble_colour;
    vec3 crest_colour;  // sunlight through a thin crest: brighter and greener than the deep water
};

// height: metres above the mean level, scaled to about [0, 1] by the caller.
vec3 scatter_term(vec3 n, vec3 v, vec3 l, float height, Roughness r, float bubbles, ScatterSettings s, vec3 sun) {
    float crest = s.scatter_crest * clamp(height, 0.0, 1.0) * pow(max(dot(l, -v), 0.0), 4.0) * pow(0.5 - 0.5 * dot(l, n), 3.0);
    float towards_viewer = s.scatter_view * pow(max(dot(v, n), 0.0), 2.0);
    vec3 scatter = (crest * s.crest_colour + towards_viewer * s.scatter_colour) * sun / (1.0 + anisotropic_lambda(n, l, r));
    scatter += s.scatter_lambert * max(dot(l, n), 0.0) * s.scatter_colour * sun + s.scatter_bubbles * bubbles * s.bubble_colour * sun;
    return scatter;
}
