// Chapter 2's lighting on the CPU, in double precision (lighting.glsl is the GPU side):
//
//   ambient  = C_ambient
//   diffuse  = C_water * C_sun * max(N.L, 0)                      Lambert, tinted blue
//   specular = C_sun * (max(N.H, 0))^shininess,  H = normalize(V + L)   Blinn-Phong
//
// The notes write H = V + L: the halfway vector must be normalised, or (N.H)^shininess grows past
// 1 and the highlight blows out. Specular is also zero where the sun is below the surface
// (N.L <= 0), so the back of a wave does not glint.
#pragma once

#include "step03_lighting/normals.hpp"

#include <algorithm>
#include <cmath>

namespace step03 {

struct Colour {
    double r = 0, g = 0, b = 0;
};

struct Light {
    Vec3 to_sun;          // L, unit
    Colour sun, water, ambient;
    double shininess = 64;
};

struct LightTerms {
    Colour ambient, diffuse, specular;
};

// The direction towards a sun at `azimuth_deg` (0 = +x, 90 = +z) and `elevation_deg` above the horizon.
inline Vec3 sun_direction(double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * step02::kTwoPi / 360.0, e = elevation_deg * step02::kTwoPi / 360.0;
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

inline LightTerms light_terms(const Vec3& normal, const Vec3& to_eye, const Light& light) {
    const double n_dot_l = dot(normal, light.to_sun);
    const double lambert = std::max(n_dot_l, 0.0);
    const Vec3 halfway = normalize({to_eye.x + light.to_sun.x, to_eye.y + light.to_sun.y, to_eye.z + light.to_sun.z});
    const double blinn = n_dot_l > 0 ? std::pow(std::max(dot(normal, halfway), 0.0), light.shininess) : 0.0;
    LightTerms t;
    t.ambient = light.ambient;
    t.diffuse = {light.water.r * light.sun.r * lambert, light.water.g * light.sun.g * lambert,
                 light.water.b * light.sun.b * lambert};
    t.specular = {light.sun.r * blinn, light.sun.g * blinn, light.sun.b * blinn};
    return t;
}

// Phong's glint (lighting.glsl's phong_specular, the step's specular=phong): the sun mirrored about
// the normal, M = 2 (N.L) N - L, against the eye, (max(M.V, 0))^(shininess / 4). In the plane of N
// and L the angle from M to V is twice the angle from N to H, and cos(2x)^(s/4) ~ cos(x)^s ~
// exp(-s x^2 / 2) near the top: the same glint as Blinn-Phong's there. Zero where N.L <= 0.
inline double phong_specular(const Vec3& normal, const Vec3& to_eye, const Light& light) {
    const double n_dot_l = dot(normal, light.to_sun);
    const Vec3 mirrored{2 * n_dot_l * normal.x - light.to_sun.x, 2 * n_dot_l * normal.y - light.to_sun.y,
                        2 * n_dot_l * normal.z - light.to_sun.z};
    return n_dot_l > 0 ? std::pow(std::max(dot(mirrored, to_eye), 0.0), light.shininess / 4) : 0.0;
}

inline Colour lit_colour(const LightTerms& t) {
    return {t.ambient.r + t.diffuse.r + t.specular.r, t.ambient.g + t.diffuse.g + t.specular.g,
            t.ambient.b + t.diffuse.b + t.specular.b};
}

}  // namespace step03
