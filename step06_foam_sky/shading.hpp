// Chapters 5.2 and 5.6 on the CPU, in double precision: the reference that shading.glsl is held
// to (step06_foam_sky.Shading.*), and the exact Fresnel equations that Schlick's curve approximates.
//
//   colour = (1 - F)(ambient + scatter) + F sky(R) + specular
//   F: Schlick, F0 + (1 - F0)(1 - N.V)^5 with F0 = 0.02 for water (n = 1.333 gives 0.0204)
//   specular = L_sun D G F / (4 N.V), G = 1 / (1 + Lambda(V) + Lambda(L))  (Smith, height-correlated),
//   D and Lambda anisotropic: alpha along the wind and across it
//   scatter: the notes' subsurface terms (Acerola's, their k1 .. k4): scatter_crest, scatter_view
//   (towards the viewer), scatter_lambert, scatter_bubbles.
#pragma once

#include "common/constants.hpp"
#include "step03_lighting/normals.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace step06 {

using step03::Vec3;

enum class Microfacet { Ggx = 0, Beckmann = 1 };  // shading.glsl's MICROFACET

constexpr double kWaterIndex = 1.333;  // refractive index of sea water (visible light)

// Reflectance at normal incidence of a dielectric of index n seen from air: ((n - 1) / (n + 1))^2.
inline double normal_incidence_reflectance(double n) { return (n - 1) * (n - 1) / ((n + 1) * (n + 1)); }

inline double fresnel_schlick(double cos_theta, double f0) {
    const double m = 1.0 - std::clamp(cos_theta, 0.0, 1.0);
    return f0 + (1.0 - f0) * m * m * m * m * m;
}

// The exact Fresnel reflectance of unpolarised light from air onto a dielectric of index n: the
// mean of the s and p reflectances, with cos_t from Snell's law (no total reflection from air).
inline double fresnel_dielectric(double cos_theta, double n) {
    const double ci = std::clamp(cos_theta, 0.0, 1.0);
    const double sin_t2 = (1.0 - ci * ci) / (n * n);
    const double ct = std::sqrt(std::max(0.0, 1.0 - sin_t2));
    const double rs = (ci - n * ct) / (ci + n * ct), rp = (n * ci - ct) / (n * ci + ct);
    return 0.5 * (rs * rs + rp * rp);
}

// Smith's Lambda for a direction at cos_theta from the normal, roughness alpha.
inline double smith_lambda(double cos_theta, double alpha, Microfacet m) {
    const double c = std::clamp(cos_theta, 1e-4, 1.0);
    const double tan2 = (1.0 - c * c) / (c * c);
    if (m == Microfacet::Ggx) return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
    const double a = 1.0 / (alpha * std::sqrt(tan2) + 1e-6);  // Walter et al.'s rational fit
    return a < 1.6 ? (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a) : 0.0;
}

// D(h), per steradian of microfacet normals: integrates to 1 against (n.h) over the hemisphere.
inline double microfacet_distribution(double n_dot_h, double alpha, Microfacet m) {
    const double c2 = n_dot_h * n_dot_h, a2 = alpha * alpha;
    if (m == Microfacet::Ggx) {
        const double d = c2 * (a2 - 1.0) + 1.0;
        return a2 / (ocean::kPi * d * d);
    }
    return std::exp((c2 - 1.0) / (a2 * c2)) / (ocean::kPi * a2 * c2 * c2);
}

// The microfacets' roughness (shading.glsl's Roughness): alpha along the wind and across it, and
// the wind's heading on the sea (wind_x, wind_z), unit length.
struct Roughness {
    double along, across, wind_x = 1, wind_z = 0;
};

inline Roughness isotropic(double alpha) { return {alpha, alpha}; }

// w's components along the wind and across it on n's tangent plane (equal-length axes: only
// their ratio, w's azimuth, is used).
inline std::pair<double, double> wind_components(const Vec3& n, const Vec3& w, const Roughness& r) {
    const double wind_n = n.x * r.wind_x + n.z * r.wind_z;
    const Vec3 along{r.wind_x - n.x * wind_n, -n.y * wind_n, r.wind_z - n.z * wind_n};
    return {step03::dot(w, along), step03::dot(w, step03::cross(n, along))};
}

// D for slopes spread as an ellipse: the isotropic D at h's azimuth's alpha (1/alpha^2 =
// cos^2/along^2 + sin^2/across^2), times alpha^2 / (along across).
inline double anisotropic_distribution(const Vec3& n, const Vec3& h, const Roughness& r, Microfacet m) {
    const auto [c, s] = wind_components(n, h, r);
    const double length2 = c * c + s * s;
    const double alpha2 = length2 > 1e-12 ? length2 / (c * c / (r.along * r.along) + s * s / (r.across * r.across))
                                          : r.along * r.along;
    return microfacet_distribution(std::max(step03::dot(n, h), 0.0), std::sqrt(alpha2), m) * alpha2 / (r.along * r.across);
}

// Smith's Lambda for direction w: the slopes projected on its azimuth, alpha^2 = cos^2 along^2 + sin^2 across^2.
inline double anisotropic_lambda(const Vec3& n, const Vec3& w, const Roughness& r, Microfacet m) {
    const auto [c, s] = wind_components(n, w, r);
    const double length2 = c * c + s * s;
    const double alpha2 =
        length2 > 1e-12 ? (c * c * r.along * r.along + s * s * r.across * r.across) / length2 : r.along * r.along;
    return smith_lambda(step03::dot(n, w), std::sqrt(alpha2), m);
}

// The sun's specular reflection towards v, per unit of sun radiance (0 with the sun or the eye
// below the surface).
inline double specular_factor(const Vec3& n, const Vec3& v, const Vec3& l, const Roughness& r, double f0, Microfacet m) {
    const double n_dot_l = step03::dot(n, l), n_dot_v = step03::dot(n, v);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0) return 0.0;
    const Vec3 h = step03::normalize({v.x + l.x, v.y + l.y, v.z + l.z});
    const double d = anisotropic_distribution(n, h, r, m);
    const double g = 1.0 / (1.0 + anisotropic_lambda(n, v, r, m) + anisotropic_lambda(n, l, r, m));
    const double f = fresnel_schlick(step03::dot(v, h), f0);
    return d * g * f / (4.0 * n_dot_v);
}

struct ScatterSettings {
    double scatter_crest, scatter_view, scatter_lambert, scatter_bubbles;  // the notes' k1 .. k4
    Vec3 scatter_colour, bubble_colour, crest_colour;
};

// shading.glsl's scatter_term, for a sun of radiance `sun`; height scaled to about [0, 1].
inline Vec3 scatter_term(const Vec3& n, const Vec3& v, const Vec3& l, double height, const Roughness& r, double bubbles,
                         const ScatterSettings& s, const Vec3& sun, Microfacet m) {
    const double back = 0.5 - 0.5 * step03::dot(l, n);
    const double crest = s.scatter_crest * std::clamp(height, 0.0, 1.0) * std::pow(std::max(-step03::dot(l, v), 0.0), 4.0) *
                         back * back * back;
    const double towards_viewer = s.scatter_view * std::pow(std::max(step03::dot(v, n), 0.0), 2.0);
    const double shadowing = 1.0 / (1.0 + anisotropic_lambda(n, l, r, m));
    const double lambert = s.scatter_lambert * std::max(step03::dot(l, n), 0.0), bubble = s.scatter_bubbles * bubbles;
    auto channel = [&](double crest_c, double scatter_c, double bubble_c, double sun_c) {
        return (crest * crest_c + towards_viewer * scatter_c) * sun_c * shadowing + lambert * scatter_c * sun_c +
               bubble * bubble_c * sun_c;
    };
    return {channel(s.crest_colour.x, s.scatter_colour.x, s.bubble_colour.x, sun.x),
            channel(s.crest_colour.y, s.scatter_colour.y, s.bubble_colour.y, sun.y),
            channel(s.crest_colour.z, s.scatter_colour.z, s.bubble_colour.z, sun.z)};
}

}  // namespace step06
