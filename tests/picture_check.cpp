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
//   picture_check whitecaps DIR FOAM WATER WHITE [DIR FOAM WATER WHITE]...
//       The whitecap coverage a camera records, as photographs are counted: the share of the picture
//       that is white. FOAM is the sea from above after >= 10 s of foam (DIR its --export, for the
//       wind speed), WATER the same frame without foam, WHITE the same frame with every texel
//       foamed; all three in linear light (tonemapper none). A pixel is whitecap where it is more
//       than halfway, in luminance, from the bare water to full foam: a threshold that a
//       photograph's own histogram would place between its two modes, here from the two
//       references. Against Monahan and O'Muircheartaigh (1980), W = 3.84e-6 U^3.41, and Callaghan,
//       de Leeuw, Cohen and O'Dowd (2008), W = 3.18e-5 (U - 3.70)^3 up to 11.25 m/s and
//       4.82e-6 (U + 1.98)^3 above (none below 3.7 m/s): within half the lower and twice the
//       higher of the two where they predict 0.2 % or more, below 0.2 % where they do not.
//   picture_check streaks DIR FOAM WATER WHITE [DIR FOAM WATER WHITE]...
//       Foam in streaks along the wind, as the Beaufort scale describes it: none below force 7
//       (13.9 m/s), "well-marked streaks" from force 8 (17.2 m/s). The same three pictures, closer
//       (streaks are tens of centimetres wide); the faint foam (cover below 0.15) must vary at least
//       twice as much across the wind as along it from force 8, at most 1.3 times below force 7.
//   picture_check detail IMAGE FROM TO
//       The detail across the view in a band of the picture (rows FROM to TO, fractions of its
//       height): the mean step in luma (display values, 0 to 255) from each pixel to its right-hand
//       neighbour. Broken ripples make it large; the horizontal smears of a sea filtered too coarsely
//       across the view make it small (step06's README, "Filtering at grazing angles"). Only prints
//       it: what it must be is the calling test's (step06_foam_sky/tests/combined_levels.sh).
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
    // The pixel (column, row) a point of the world falls in: ray's inverse.
    glm::ivec2 pixel(const glm::dvec3& point, int width, int height) const {
        const glm::dvec3 d = point - eye;
        const double depth = glm::dot(d, forward);
        const double x = glm::dot(d, right) / depth / (tan_half_fov * aspect), y = glm::dot(d, up) / depth / tan_half_fov;
        return {int(std::floor((x + 1) / 2 * width)), int(std::floor((1 - y) / 2 * height))};
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

double luminance(const std::uint8_t* rgba) {
    return 0.2126 * srgb_to_linear(rgba[0] / 255.0) + 0.7152 * srgb_to_linear(rgba[1] / 255.0) +
           0.0722 * srgb_to_linear(rgba[2] / 255.0);
}

ocean::Image load(const std::string& path) {
    std::string error;
    auto image = ocean::load_image(path, &error);
    if (!image) throw std::runtime_error(error);
    return *image;
}

double monahan(double u) { return 3.84e-6 * std::pow(u, 3.41); }
double callaghan(double u) {
    if (u <= 3.70) return 0;
    return u <= 11.25 ? 3.18e-5 * std::pow(u - 3.70, 3) : 4.82e-6 * std::pow(u + 1.98, 3);
}

// How far each pixel is from the bare water to full foam, in luminance: 0 water, 1 white, -1 where
// foam cannot be told from water (no brighter than it).
struct FoamCover {
    int width = 0, height = 0;
    std::vector<double> cover;
    double at(int i, int j) const { return i < 0 || j < 0 || i >= width || j >= height ? -1 : cover[std::size_t(j) * width + i]; }
};
FoamCover foam_cover(const ocean::Image& foam, const ocean::Image& water, const ocean::Image& white) {
    if (foam.width != water.width || foam.width != white.width || foam.height != water.height || foam.height != white.height)
        throw std::runtime_error("the three pictures differ in size");
    FoamCover c{foam.width, foam.height, std::vector<double>(std::size_t(foam.width) * foam.height, -1)};
    for (std::size_t p = 0; p < foam.rgba.size(); p += 4) {
        const double lw = luminance(&water.rgba[p]), lf = luminance(&foam.rgba[p]), lwhite = luminance(&white.rgba[p]);
        if (lwhite > lw) c.cover[p / 4] = std::clamp((lf - lw) / (lwhite - lw), 0.0, 1.0);
    }
    return c;
}

// Streaks along the wind: how much the faint foam (the cover capped at `faint`, so the whitecaps'
// solid white counts no more than the lingering foam) changes over `step` metres of sea across the
// wind against along it (mean squared differences; each pixel's point on the mean level, its
// neighbour found by projecting back into the picture). Above 1: the foam lies in lines along the
// wind; about 1: no direction; below 1: along the crests, across the wind.
double streakiness(const Export& e, const FoamCover& c, double step, double faint) {
    const Pinhole camera = pinhole(e, c.width, c.height);
    const double wind = radians(number(e, "wind_direction"));
    const glm::dvec3 along(std::cos(wind), 0, std::sin(wind)), across(-std::sin(wind), 0, std::cos(wind));
    auto cover_at = [&](const glm::dvec3& point) {
        const glm::ivec2 at = camera.pixel(point, c.width, c.height);
        return c.at(at.x, at.y);
    };
    double changes_along = 0, changes_across = 0;
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            const double here = c.at(i, j);
            const glm::dvec3 ray = camera.ray(i, j, c.width, c.height);
            if (here < 0 || ray.y >= -1e-3) continue;
            const glm::dvec3 point = camera.eye + ray * (-camera.eye.y / ray.y);
            double a = cover_at(point + step * along), b = cover_at(point + step * across);
            if (a < 0 || b < 0) continue;
            a = std::min(a, faint), b = std::min(b, faint);
            const double here_faint = std::min(here, faint);
            changes_along += (a - here_faint) * (a - here_faint);
            changes_across += (b - here_faint) * (b - here_faint);
        }
    return changes_along > 0 ? changes_across / changes_along : 0.0;
}

// Per sea: its export, and its cover from the three pictures that follow it in `args`.
template <typename Check>
int for_each_sea(const std::vector<std::string>& args, Check check) {
    int failures = 0;
    for (std::size_t k = 0; k + 3 < args.size(); k += 4) {
        const Export e = ocean_test::read_export(args[k]);
        const ocean::Image foam = load(args[k + 1]), water = load(args[k + 2]), white = load(args[k + 3]);
        long clipped = 0;
        for (std::size_t p = 0; p < white.rgba.size(); p += 4)
            clipped += white.rgba[p] == 255 || white.rgba[p + 1] == 255 || white.rgba[p + 2] == 255;
        if (clipped > 0) std::printf("%s: the white reference clips: lower the exposure\n", args[k].c_str()), ++failures;
        const FoamCover cover = foam_cover(foam, water, white);
        long compared = 0;
        for (double c : cover.cover) compared += c >= 0;
        if (compared < long(cover.cover.size()) / 2) throw std::runtime_error(args[k] + ": foam is not brighter than the water");
        failures += check(args[k], e, cover) ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}

int streaks(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        const double wind = number(e, "wind_speed"), ratio = streakiness(e, cover, 0.3, 0.15);
        const char* rule = wind >= 17.2 ? "Beaufort 8 and above, well-marked streaks: must be >= 2"
                         : wind < 13.9  ? "below Beaufort 7, no streaks: must be <= 1.3"
                                        : "Beaufort 7, streaks begin: not held";
        std::printf("%s: U = %4.1f m/s, the faint foam varies %.2f times more across the wind than along it (%s)\n",
                    dir.c_str(), wind, ratio, rule);
        return wind >= 17.2 ? ratio >= 2 : wind < 13.9 ? ratio <= 1.3 : true;
    });
}

int whitecaps(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        long covered = 0, compared = 0;  // whitecap: more than halfway from the water to full foam
        for (double c : cover.cover) covered += c > 0.5, compared += c >= 0;
        const double wind = number(e, "wind_speed"), seen = double(covered) / double(compared);
        const double low = std::min(monahan(wind), callaghan(wind)), high = std::max(monahan(wind), callaghan(wind));
        const bool some = high >= 0.002;
        std::printf("%s: U = %4.1f m/s, whitecaps cover %6.2f %% of the picture; Monahan %5.2f %%, Callaghan %5.2f %% (%s)\n",
                    dir.c_str(), wind, 100 * seen, 100 * monahan(wind), 100 * callaghan(wind),
                    some ? "within half the lower, twice the higher" : "must be < 0.2 %");
        return some ? seen >= low / 2 && seen <= 2 * high : seen < 0.002;
    });
}

double fraction(const std::string& text) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size()) throw std::runtime_error("detail: '" + text + "' is not a number");
    return value;
}

int detail(const std::string& path, double from, double to) {
    if (!(from >= 0 && from < to && to <= 1)) throw std::runtime_error("detail: the band must be 0 <= FROM < TO <= 1");
    const ocean::Image image = load(path);
    const auto luma = [&](int x, int y) {
        const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    double sum = 0;
    long steps = 0;
    for (int y = int(from * image.height); y < int(to * image.height); ++y)
        for (int x = 1; x < image.width; ++x, ++steps) sum += std::abs(luma(x, y) - luma(x - 1, y));
    if (steps == 0) throw std::runtime_error("detail: '" + path + "' has no pixels in the band");
    std::printf("%s: detail across the view %.3f\n", path.c_str(), sum / double(steps));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "glitter" && argc >= 4 && argc % 2 == 0) return glitter(std::vector<std::string>(argv + 2, argv + argc));
        if ((mode == "whitecaps" || mode == "streaks") && argc >= 6 && (argc - 2) % 4 == 0) {
            const std::vector<std::string> args(argv + 2, argv + argc);
            return mode == "whitecaps" ? whitecaps(args) : streaks(args);
        }
        if (mode == "detail" && argc == 5) return detail(argv[2], fraction(argv[3]), fraction(argv[4]));
        std::fprintf(stderr, "usage: picture_check glitter DIR IMAGE [DIR IMAGE]... | whitecaps|streaks DIR FOAM WATER WHITE... | "
                             "detail IMAGE FROM TO\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "picture_check: %s\n", e.what());
        return 2;
    }
}
