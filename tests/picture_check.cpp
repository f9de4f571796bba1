// picture_check: what a camera at sea would record, measured on a step's rendered picture (its
// screenshot) and the parameters its --export wrote beside it. Like physics_check, it knows nothing
// of the shaders or the spectrum: only the camera's model (a pinhole: yaw, pitch, distance to the
// target, vertical field of view, as --list-params describes them), the sun's direction and the
// Fresnel reflectance of water.
//
//   picture_check glitter DIR IMAGE [DIR IMAGE]...
//       The sea's mean square slope, read from the sun's glitter as Cox and Munk (1954) read it from
//       their aerial photographs. IMAGE is the sea seen from above with only the sun's specular
//       reflection drawn (linear light, nothing clipped: tonemapper none). A pixel whose ray leaves
//       the eye along -v sees the sun only on facets facing h = normalize(v + l); their slopes are
//       s = -(h_x, h_z) / h_y, and the picture's brightness there is
//           I = L_sun F(v.h) p(s) / (4 cos^4(beta) (n.v))       (beta: h's tilt, n = up)
//       so p(s) follows from I up to a constant. Binned by slope and fitted by least squares,
//       ln p = c - a s_u^2 - b s_c^2 - e s_u s_c (s_u along the wind, s_c across it) gives the
//       slopes' variance along and across the ellipse's axes, and the axes' heading. Masking is
//       left out: for slopes within this field of view (under 0.6) and alpha under 0.4 Smith's
//       Lambda of Beckmann's distribution is 0.
//       A sea with wind_speed 0 must give back the set roughness (alpha^2 = 2 sigma^2 per axis)
//       within 5 %: the method's own check. A wind sea must match Cox and Munk's clean-sea fit
//       (total, upwind and crosswind within 25 %; U taken from 10 m to their 12.5 m on a
//       logarithmic profile, z0 = 2e-4 m), upwind above crosswind, the ellipse's long axis within
//       20 degrees of the wind.
// Prints the figures; exit 0 when they hold, 1 otherwise (and 2 on bad input).
#include "common/image.hpp"
#include "tests/export_reader.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using ocean_test::Export;
using ocean_test::number;

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees) { return degrees * kPi / 180; }

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The exact reflectance of unpolarised light on water (n = 1.333), not the renderer's Schlick.
double fresnel_water(double cos_i) {
    const double n = 1.333, ct = std::sqrt(std::max(0.0, 1 - (1 - cos_i * cos_i) / (n * n)));
    const double rs = (cos_i - n * ct) / (cos_i + n * ct), rp = (n * cos_i - ct) / (n * cos_i + ct);
    return 0.5 * (rs * rs + rp * rp);
}

// Cox and Munk's clean sea, U at 12.5 m: upwind 3.16e-3 U, crosswind 0.003 + 1.92e-3 U.
struct Slopes {
    double upwind = 0, crosswind = 0;
    double total() const { return upwind + crosswind; }
};
Slopes cox_munk(double wind_10m) {
    const double u = wind_10m * std::log(12.5 / 2e-4) / std::log(10 / 2e-4);
    return {3.16e-3 * u, 0.003 + 1.92e-3 * u};
}

// The ray through the centre of pixel (i, j) (row 0 at the top), from the camera's parameters.
struct Pinhole {
    glm::dvec3 eye, forward, right, up;
    double tan_half_fov, aspect;
    glm::dvec3 ray(int i, int j, int width, int height) const {
        const double x = (2 * (i + 0.5) / width - 1) * tan_half_fov * aspect, y = (1 - 2 * (j + 0.5) / height) * tan_half_fov;
        return glm::normalize(forward + x * right + y * up);
    }
};
Pinhole pinhole(const Export& e, int width, int height) {
    const double yaw = radians(number(e, "camera_yaw")), pitch = radians(number(e, "camera_pitch"));
    Pinhole p;
    p.forward = {std::cos(pitch) * std::sin(yaw), -std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
    const glm::dvec3 target(number(e, "camera_target_x"), number(e, "camera_target_y"), number(e, "camera_target_z"));
    p.eye = target - p.forward * number(e, "camera_distance");
    p.right = glm::normalize(glm::cross(p.forward, glm::dvec3(0, 1, 0)));
    p.up = glm::cross(p.right, p.forward);
    p.tan_half_fov = std::tan(radians(number(e, "camera_fov")) / 2);
    p.aspect = double(width) / height;
    return p;
}

struct GlitterFit {
    Slopes along_axes;           // variance along the wind and across it
    double major_heading = 0;    // the ellipse's long axis, degrees from the wind
    int bins = 0, clipped = 0;
};

// The slope density from the picture, binned and fitted (see the top of the file).
GlitterFit fit_glitter(const Export& e, const ocean::Image& image) {
    const Pinhole camera = pinhole(e, image.width, image.height);
    const double azimuth = radians(number(e, "sun_azimuth")), elevation = radians(number(e, "sun_elevation"));
    const glm::dvec3 to_sun(std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth));
    const double wind = radians(number(e, "wind_direction"));
    const glm::dvec2 along(std::cos(wind), std::sin(wind)), across(-std::sin(wind), std::cos(wind));
    constexpr double kBin = 0.02;  // slope units
    struct Bin {
        double su = 0, sc = 0, density = 0;
        int count = 0;
    };
    std::map<std::pair<int, int>, Bin> bins;
    GlitterFit fit;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const glm::dvec3 ray = camera.ray(i, j, image.width, image.height);
            if (ray.y >= -1e-3) continue;  // above the horizon
            const glm::dvec3 v = -ray, h = glm::normalize(v + to_sun);
            const std::uint8_t* rgba = &image.rgba[(std::size_t(j) * image.width + i) * 4];
            if (rgba[0] == 255 || rgba[1] == 255 || rgba[2] == 255) {
                ++fit.clipped;
                continue;
            }
            const double radiance = srgb_to_linear(rgba[0] / 255.0) + srgb_to_linear(rgba[1] / 255.0) + srgb_to_linear(rgba[2] / 255.0);
            const double cos_beta = h.y, density = radiance * 4 * v.y * std::pow(cos_beta, 4) / fresnel_water(glm::dot(v, h));
            const glm::dvec2 slope(-h.x / h.y, -h.z / h.y);
            const double su = glm::dot(slope, along), sc = glm::dot(slope, across);
            Bin& b = bins[{int(std::floor(su / kBin)), int(std::floor(sc / kBin))}];
            b.su += su, b.sc += sc, b.density += density, ++b.count;
        }
    double peak = 0;
    for (auto& [key, b] : bins) {
        b.su /= b.count, b.sc /= b.count, b.density /= b.count;
        peak = std::max(peak, b.density);
    }
    // ln p = c - a su^2 - b sc^2 - e su sc, weighted by the pixels in each bin, over the bins
    // brighter than 2 % of the brightest (the 8-bit picture's darker steps are coarse).
    double m[4][4] = {}, r[4] = {};
    for (const auto& [key, b] : bins) {
        if (b.count < 3 || b.density < 0.02 * peak) continue;
        const double x[4] = {1, -b.su * b.su, -b.sc * b.sc, -b.su * b.sc}, y = std::log(b.density);
        for (int p = 0; p < 4; ++p) {
            r[p] += b.count * x[p] * y;
            for (int q = 0; q < 4; ++q) m[p][q] += b.count * x[p] * x[q];
        }
        ++fit.bins;
    }
    if (fit.bins < 20) throw std::runtime_error("too few bright slope bins to fit the glitter (" + std::to_string(fit.bins) + ")");
    // Gauss-Jordan on the 4 x 4 normal equations.
    for (int c = 0; c < 4; ++c) {
        int pivot = c;
        for (int k = c + 1; k < 4; ++k)
            if (std::abs(m[k][c]) > std::abs(m[pivot][c])) pivot = k;
        std::swap(m[c], m[pivot]);
        std::swap(r[c], r[pivot]);
        for (int k = 0; k < 4; ++k) {
            if (k == c) continue;
            const double f = m[k][c] / m[c][c];
            for (int q = 0; q < 4; ++q) m[k][q] -= f * m[c][q];
            r[k] -= f * r[c];
        }
    }
    const double a = r[1] / m[1][1], b = r[2] / m[2][2], cross = r[3] / m[3][3];
    // p ~ exp(-s^T Q s), Q = [[a, cross/2], [cross/2, b]]: the covariance is Q^-1 / 2.
    const double det = a * b - cross * cross / 4;
    if (!(a > 0 && b > 0 && det > 0)) throw std::runtime_error("the glitter does not fall off from its centre");
    fit.along_axes = {b / (2 * det), a / (2 * det)};
    // The long axis of the ellipse: the eigenvector of Q with the smaller eigenvalue.
    fit.major_heading = 0.5 * std::atan2(-cross, b - a) * 180 / kPi;
    return fit;
}

int glitter(const std::vector<std::string>& args) {
    int failures = 0;
    for (std::size_t k = 0; k + 1 < args.size(); k += 2) {
        const Export e = ocean_test::read_export(args[k]);
        std::string error;
        const auto image = ocean::load_image(args[k + 1], &error);
        if (!image) throw std::runtime_error(error);
        if (number(e, "sun_elevation") < 60) throw std::runtime_error(args[k] + ": the sun must stand high (elevation >= 60)");
        const GlitterFit fit = fit_glitter(e, *image);
        const double wind = number(e, "wind_speed");
        const Slopes seen = fit.along_axes;
        std::printf("%s: U = %4.1f m/s, the glitter's mean square slope %.4f (along the wind %.4f, across %.4f; "
                    "long axis %+.1f degrees from the wind; %d bins, %d pixels clipped)\n",
                    args[k].c_str(), wind, seen.total(), seen.upwind, seen.crosswind, fit.major_heading, fit.bins,
                    fit.clipped);
        if (fit.clipped > image->width * image->height / 1000)
            std::printf("  more than 0.1 %% of the pixels clipped: lower the exposure\n"), ++failures;
        if (wind == 0) {
            const double alpha = number(e, "roughness");
            const double ratio = seen.total() / (alpha * alpha);
            std::printf("  flat sea, roughness %.3f: alpha^2 = %.4f, read back %.3f of it (within 5 %%)\n", alpha,
                        alpha * alpha, ratio);
            failures += std::abs(ratio - 1) <= 0.05 ? 0 : 1;
            continue;
        }
        const Slopes cm = cox_munk(wind);
        const double total = seen.total() / cm.total(), up = seen.upwind / cm.upwind, cross = seen.crosswind / cm.crosswind;
        std::printf("  Cox and Munk %.4f (upwind %.4f, crosswind %.4f): ours %.2f of theirs (upwind %.2f, crosswind "
                    "%.2f; within 25 %%)\n",
                    cm.total(), cm.upwind, cm.crosswind, total, up, cross);
        failures += std::abs(total - 1) <= 0.25 && std::abs(up - 1) <= 0.25 && std::abs(cross - 1) <= 0.25 ? 0 : 1;
        if (wind >= 7) {
            const bool along_wind = seen.upwind > seen.crosswind && std::abs(fit.major_heading) <= 20;
            if (!along_wind) std::printf("  the glitter is not longer along the wind\n");
            failures += along_wind ? 0 : 1;
        }
    }
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "glitter" && argc >= 4 && argc % 2 == 0) return glitter(std::vector<std::string>(argv + 2, argv + argc));
        std::fprintf(stderr, "usage: picture_check glitter DIR IMAGE [DIR IMAGE]...\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "picture_check: %s\n", e.what());
        return 2;
    }
}
