// picture_check: what a camera at sea would record of step06's sea, measured on the chapter's
// rendered pictures (its screenshots) and the parameters its --export wrote beside them: the sun's
// glitter against Cox and Munk's photographs, the whitecaps against the coverage photographs count
// at sea. Like physics_check, it knows nothing of the shaders or the spectrum: only the camera's
// model (tests/picture_camera.hpp's pinhole), the sun's direction and the Fresnel reflectance of
// water. The tests that run it: glitter.sh and whitecaps.sh beside it (CMakeLists.txt).
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
//       foamed; all three in linear light (tonemapper none). Each pixel's cover is how far it is, in
//       luminance, from the bare water to full foam. Foam comes in two stages, which photographs
//       separate by brightness (Monahan and Lu 1990): the active whitecap (stage A), as bright as
//       the white reference or nearly, and the residual foam it leaves (stage B), greyer. A pixel is
//       whitecap, of either stage, where its cover is above 0.25: the residual foam sends back half
//       of fresh foam's light where its lace covers a pixel (0.5 to 0.62 of the white reference,
//       whose active foam's brightness varies), less over a 1 m pixel that averages its holes, and
//       whitecap counts include it. Against Monahan and O'Muircheartaigh (1980), W = 3.84e-6 U^3.41, and
//       Callaghan, de Leeuw, Cohen and O'Dowd (2008), W = 3.18e-5 (U - 3.70)^3 up to 11.25 m/s and
//       4.82e-6 (U + 1.98)^3 above (none below 3.7 m/s): within half the lower and twice the
//       higher of the two where they predict 0.2 % or more, below 0.2 % where they do not.
//   picture_check stages DIR FOAM WATER WHITE [DIR FOAM WATER WHITE]...
//       The same pictures split into the two stages: W (cover above 0.25), W_A, the active
//       whitecaps (cover above 0.6, which no residual foam reaches), and W_A / W. Monahan and Lu's
//       split is W_B = 9.7 W_A, so W_A / W = 1 / 10.7 = 0.093; it must hold within a factor of 2
//       where W >= 0.2 %. The split is taken from a public implementation of their law (github
//       edinnat/Ocean-reference-model-mirror, Ocean/Foam/MonahanLu.f: Wa = Wb / 9.7), not from
//       the paper itself, which we could not read.
//   picture_check edges DIR FOAM WATER WHITE [DIR FOAM WATER WHITE]...
//       Foam's edges are soft: a raft of bubbles thins out over its last tens of centimetres. At
//       each foam pixel (cover above 0.25) with a 4-neighbour of water, the cover is read across the
//       edge (along the gradient of the cover smoothed over 1.5 pixels; bilinear, every quarter
//       pixel, 10 pixels either side), and the edge's width is its rise from 10 % to 90 % of the way
//       from the local water (the lowest cover before it) to the local patch (the highest after
//       it), in metres on the sea (the two points projected through the pinhole) and in pixels.
//       An edge drawn within a pixel rises in under one (a step between two pixels' centres reads
//       0.8). The median must be at least 0.3 m (the bubble pattern's cells are about 0.9 m and
//       0.33 m), and under 25 % of the edges may rise within one pixel. On pictures whose pixels are
//       smaller than that: from 40 m straight down, 0.26 m (from 150 m, 0.98 m, an edge is a pixel).
//   picture_check streaks DIR FOAM WATER WHITE [DIR FOAM WATER WHITE]...
//       Foam in streaks along the wind, as the Beaufort scale describes it: none below force 7
//       (13.9 m/s), "well-marked streaks" from force 8 (17.2 m/s). The same three pictures, closer
//       (streaks are tens of centimetres wide); the faint foam (cover capped at 0.15) must vary at
//       least twice as much across the wind as along it from force 8, at most 1.3 times below
//       force 7. And its correlation lengths on the sea along the wind and across it (each pixel's
//       point on the mean level, its partner a lag away found by projecting back into the picture):
//       the lag where the faint foam's autocorrelation first falls below 1/e. Capped, because the
//       whitecaps' bright round patches would otherwise carry most of the variance and set both
//       lengths (on a picture with streaks: 0.5 m across capped, 2.3 m not). From force 8 the
//       streaks are broken filaments: along the wind a finite length, under a third of the view's
//       width on the sea (not lines across the view) and at least 3 times the length across it,
//       which is under 1.5 m.
//   picture_check agree A_DIR A_FOAM A_WATER A_WHITE B_DIR B_FOAM B_WATER B_WHITE [...]
//       The same sea at the same time through two cameras (as whitecaps takes its pictures), e.g.
//       from above and from the deck, records the same foam. Both pictures' covers are read on a
//       0.25 m grid of the sea's mean level (each point projected into each picture through its
//       own pinhole), over the points both see 5 to 60 m from their eyes (nearer, the eye is in the
//       waves; farther, a deck camera's pixels stretch along the view). Held: the mean cover there,
//       the light the foam sends back, which is the same at any pixel size where the renderer
//       filters rightly (a count above a threshold is not: on lace a fine pixel sees bright
//       borders above it where a coarse one averages the holes in below it). They agree when the
//       ratio of the two means is within [0.67, 1.5], or when they differ by at most 3 standard
//       errors, one being the mean over the root of the mean number of whitecap patches (cover
//       above 0.25; with few patches, one more or less is a large step). Seas with under 0.2 %
//       whitecaps are not held. Also prints the whitecap shares, and both by distance from B's eye.
//   picture_check detail IMAGE FROM TO
//       The detail across the view in a band of the picture (rows FROM to TO, fractions of its
//       height): the mean step in luma (display values, 0 to 255) from each pixel to its right-hand
//       neighbour. Broken ripples make it large; the horizontal smears of a sea filtered too coarsely
//       across the view make it small (sea.md, "Filtering at grazing angles"). Only prints it, for
//       measuring by hand (docs/performance.md): no test holds it to a value.
// Prints the figures; exit 0 when they hold, 1 otherwise (and 2 on bad input).
#include "step06_foam_sky/tests/streak_lines.hpp"
#include "tests/picture_camera.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using ocean_test::Export;
using ocean_test::load_picture;
using ocean_test::luminance;
using ocean_test::number;
using ocean_test::Pinhole;
using ocean_test::pinhole;
using ocean_test::radians;
using ocean_test::srgb_to_linear;

constexpr double kPi = 3.14159265358979323846;

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

double monahan(double u) { return 3.84e-6 * std::pow(u, 3.41); }
double callaghan(double u) {
    if (u <= 3.70) return 0;
    return u <= 11.25 ? 3.18e-5 * std::pow(u - 3.70, 3) : 4.82e-6 * std::pow(u + 1.98, 3);
}

// The stages photographs separate by brightness (Monahan and Lu 1990). A pixel is whitecap, of
// either stage, above this cover: the residual foam is greyer, half fresh foam's brightness where its
// lace covers a pixel and less over a pixel that averages its holes, and photograph analyses count
// it; halfway (0.5) would leave it out.
constexpr double kWhitecapCover = 0.25;
// And an active whitecap (stage A) above this: over the census' 1 m pixels, which average the lace's
// holes, no residual foam reaches it (a fine pixel on a lace border can: 0.5 to 0.62).
constexpr double kActiveCover = 0.6;
// Monahan and Lu's split, W_B = 9.7 W_A (MonahanLu.f of github edinnat/Ocean-reference-model-mirror:
// Wa = Wb / 9.7): the active share of all whitecap is 1 / 10.7.
constexpr double kActiveShare = 1 / (1 + 9.7);

// How far each pixel is from the bare water to full foam, in luminance: 0 water, 1 white, -1 where
// foam cannot be told from water (no brighter than it).
struct FoamCover {
    int width = 0, height = 0;
    std::vector<double> cover;
    double at(int i, int j) const { return i < 0 || j < 0 || i >= width || j >= height ? -1 : cover[std::size_t(j) * width + i]; }
    // At a position in the picture (Pinhole's units), bilinear between the pixels' centres; -1
    // where one of the four is.
    double bilinear(glm::dvec2 position) const {
        const double x = position.x - 0.5, y = position.y - 0.5;
        const int i = int(std::floor(x)), j = int(std::floor(y));
        const double fx = x - i, fy = y - j, c00 = at(i, j), c10 = at(i + 1, j), c01 = at(i, j + 1), c11 = at(i + 1, j + 1);
        if (c00 < 0 || c10 < 0 || c01 < 0 || c11 < 0) return -1;
        return (c00 * (1 - fx) + c10 * fx) * (1 - fy) + (c01 * (1 - fx) + c11 * fx) * fy;
    }
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

// The share of the picture's pixels (those with a cover) whose cover is above `level`.
double share_above(const FoamCover& c, double level) {
    long above = 0, compared = 0;
    for (double v : c.cover) above += v > level, compared += v >= 0;
    return compared > 0 ? double(above) / double(compared) : 0.0;
}

glm::dvec3 along_wind(const Export& e) {
    const double wind = radians(number(e, "wind_direction"));
    return {std::cos(wind), 0, std::sin(wind)};
}
glm::dvec3 across_wind(const Export& e) { return glm::cross(along_wind(e), glm::dvec3(0, 1, 0)); }

// Streaks along the wind: how much the faint foam (the cover capped at `faint`, so the whitecaps'
// solid white counts no more than the lingering foam) changes over `step` metres of sea across the
// wind against along it (mean squared differences; each pixel's point on the mean level, its
// neighbour found by projecting back into the picture). Above 1: the foam lies in lines along the
// wind; about 1: no direction; below 1: along the crests, across the wind.
double streakiness(const Export& e, const FoamCover& c, double step, double faint) {
    const Pinhole camera = pinhole(e, c.width, c.height);
    const glm::dvec3 along = along_wind(e), across = across_wind(e);
    auto cover_at = [&](const glm::dvec3& point) {
        const glm::ivec2 at = camera.pixel(point, c.width, c.height);
        return c.at(at.x, at.y);
    };
    double changes_along = 0, changes_across = 0;
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            const double here = c.at(i, j);
            const auto point = camera.ground(camera.ray(i, j, c.width, c.height));
            if (here < 0 || !point) continue;
            double a = cover_at(*point + step * along), b = cover_at(*point + step * across);
            if (a < 0 || b < 0) continue;
            a = std::min(a, faint), b = std::min(b, faint);
            const double here_faint = std::min(here, faint);
            changes_along += (a - here_faint) * (a - here_faint);
            changes_across += (b - here_faint) * (b - here_faint);
        }
    return changes_along > 0 ? changes_across / changes_along : 0.0;
}

// The faint foam's correlation with itself `lag` metres of sea away along `direction`: Pearson's,
// over the pixels (each at its point on the mean level) whose point a lag away is in the picture,
// read there between the pixels' centres (bilinear: lags shorter than a pixel count).
double correlation(const Pinhole& camera, const FoamCover& c, const std::vector<glm::dvec3>& points,
                   const std::vector<double>& values, glm::dvec3 direction, double lag, double faint) {
    double n = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double b = c.bilinear(camera.position(points[p] + lag * direction, c.width, c.height));
        if (b < 0) continue;
        const double a = values[p], bf = std::min(b, faint);
        n += 1, sa += a, sb += bf, saa += a * a, sbb += bf * bf, sab += a * bf;
    }
    const double va = saa - sa * sa / n, vb = sbb - sb * sb / n;
    return n > 1 && va > 0 && vb > 0 ? (sab - sa * sb / n) / std::sqrt(va * vb) : 0.0;
}

// The correlation length of the faint foam along `direction`: the lag where its correlation first
// falls below 1/e (linear between steps of `step` metres), infinity where it does not within `reach`.
double correlation_length(const Export& e, const FoamCover& c, glm::dvec3 direction, double faint, double step, double reach) {
    const Pinhole camera = pinhole(e, c.width, c.height);
    std::vector<glm::dvec3> points;
    std::vector<double> values;
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            const auto point = camera.ground(camera.ray(i, j, c.width, c.height));
            if (c.at(i, j) < 0 || !point) continue;
            points.push_back(*point);
            values.push_back(std::min(c.at(i, j), faint));
        }
    const double level = std::exp(-1.0);
    double previous = 1;  // at lag 0
    for (double lag = step; lag <= reach; lag += step) {
        const double r = correlation(camera, c, points, values, direction, lag, faint);
        if (r < level) return lag - step * (level - r) / (previous - r);
        previous = r;
    }
    return INFINITY;
}

// The width of the picture's middle row on the sea, metres.
double view_width(const Pinhole& camera, int width, int height) {
    const auto left = camera.ground(camera.ray_through({0, height / 2.0}, width, height));
    const auto right = camera.ground(camera.ray_through({double(width), height / 2.0}, width, height));
    if (!left || !right) throw std::runtime_error("the picture's middle row does not all see the sea");
    return glm::length(*right - *left);
}

// Soft edges. The cover smoothed over a Gaussian of 1.5 pixels (the pixels that have one): its
// gradient gives the direction across an edge, steadied against the bubble pattern's holes.
std::vector<double> smoothed(const FoamCover& c) {
    constexpr int kRadius = 4;
    constexpr double kSigma = 1.5;
    std::vector<double> out(c.cover.size(), -1);
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            double sum = 0, weights = 0;
            for (int dj = -kRadius; dj <= kRadius; ++dj)
                for (int di = -kRadius; di <= kRadius; ++di) {
                    const double v = c.at(i + di, j + dj), w = std::exp(-(di * di + dj * dj) / (2 * kSigma * kSigma));
                    if (v >= 0) sum += w * v, weights += w;
                }
            if (weights > 0) out[std::size_t(j) * c.width + i] = sum / weights;
        }
    return out;
}

// An edge's profile is read from 10 pixels before it to 10 after, in steps of a quarter pixel.
constexpr double kProfileReach = 10, kProfileStep = 0.25;
// Rises under this (from the water's cover to the patch's) are the pattern's flicker, not an edge.
constexpr double kMinEdgeContrast = 0.2;

// Where a profile (samples along the direction the cover rises, its middle on a foam pixel at an
// edge) rises from 10 % to 90 % of the way from the local water (its lowest cover on the water side
// of the edge, back to where it was foam again) to the local patch (its highest on the foam side,
// on to where it is water again): the two positions, fractional samples; none where the profile
// has no edge before its middle or the rise is under kMinEdgeContrast.
std::optional<glm::dvec2> rise_10_90(const std::vector<double>& v) {
    const int count = int(v.size());
    int edge = count / 2;  // the last water sample before the middle's foam
    while (edge >= 0 && v[edge] > kWhitecapCover) --edge;
    if (edge < 0) return std::nullopt;
    int lowest = edge, highest = edge + 1;
    for (int k = edge; k >= 0 && v[k] <= kWhitecapCover; --k)
        if (v[k] < v[lowest]) lowest = k;
    for (int k = edge + 1; k < count && v[k] > kWhitecapCover; ++k)
        if (v[k] > v[highest]) highest = k;
    const double water = v[lowest], patch = v[highest];
    if (patch - water < kMinEdgeContrast) return std::nullopt;
    const double low = water + 0.1 * (patch - water), high = water + 0.9 * (patch - water);
    int a = highest;  // the last sample at or below `low` before the patch's highest
    while (v[a] > low) --a;
    int b = a + 1;  // the first at or above `high` after it
    while (v[b] < high) ++b;
    return glm::dvec2(a + (low - v[a]) / (v[a + 1] - v[a]), b - 1 + (high - v[b - 1]) / (v[b] - v[b - 1]));
}

struct Rise {
    double pixels = 0, metres = 0;
};

// The 10 %-90 % rise of the edge at foam pixel (i, j), across it (along the smoothed cover's
// gradient); in metres between the two points on the sea. None where the profile leaves the
// picture or has no edge to measure.
std::optional<Rise> edge_rise(const FoamCover& c, const std::vector<double>& smooth, const Pinhole& camera, int i, int j) {
    const auto s = [&](int x, int y) { return smooth[std::size_t(std::clamp(y, 0, c.height - 1)) * c.width + std::clamp(x, 0, c.width - 1)]; };
    glm::dvec2 gradient(s(i + 1, j) - s(i - 1, j), s(i, j + 1) - s(i, j - 1));
    if (glm::length(gradient) < 1e-3) return std::nullopt;
    const glm::dvec2 centre(i + 0.5, j + 0.5), across = glm::normalize(gradient);
    const int steps = int(std::lround(kProfileReach / kProfileStep));
    std::vector<double> profile;
    for (int k = -steps; k <= steps; ++k) {
        profile.push_back(c.bilinear(centre + k * kProfileStep * across));
        if (profile.back() < 0) return std::nullopt;
    }
    const auto rise = rise_10_90(profile);
    if (!rise) return std::nullopt;
    const auto at = [&](double sample) { return centre + (sample - steps) * kProfileStep * across; };
    const auto from = camera.ground(camera.ray_through(at(rise->x), c.width, c.height));
    const auto to = camera.ground(camera.ray_through(at(rise->y), c.width, c.height));
    if (!from || !to) return std::nullopt;
    return Rise{(rise->y - rise->x) * kProfileStep, glm::length(*to - *from)};
}

// The rises of every foam patch's edge in the picture: at each foam pixel (cover above
// kWhitecapCover) with a 4-neighbour of water.
std::vector<Rise> edge_rises(const Export& e, const FoamCover& c) {
    const Pinhole camera = pinhole(e, c.width, c.height);
    const std::vector<double> smooth = smoothed(c);
    const auto water = [&](int i, int j) { return c.at(i, j) >= 0 && c.at(i, j) <= kWhitecapCover; };
    std::vector<Rise> rises;
    for (int j = 0; j < c.height; ++j)
        for (int i = 0; i < c.width; ++i) {
            if (c.at(i, j) <= kWhitecapCover) continue;
            if (!water(i - 1, j) && !water(i + 1, j) && !water(i, j - 1) && !water(i, j + 1)) continue;
            if (const auto rise = edge_rise(c, smooth, camera, i, j)) rises.push_back(*rise);
        }
    return rises;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// A sea's export and its foam's cover from the three pictures: args[k] to args[k + 3].
struct Sea {
    std::string dir;
    Export e;
    FoamCover cover;
};
Sea load_sea(const std::vector<std::string>& args, std::size_t k, int& failures) {
    Sea sea{args[k], ocean_test::read_export(args[k]), {}};
    const ocean::Image foam = load_picture(args[k + 1]), water = load_picture(args[k + 2]), white = load_picture(args[k + 3]);
    sea.cover = foam_cover(foam, water, white);
    // Only where foam is measured: a low camera's sky (the sun's disc) is the same in all three.
    long clipped = 0;
    for (std::size_t p = 0; p < white.rgba.size(); p += 4)
        clipped += sea.cover.cover[p / 4] >= 0 && (white.rgba[p] == 255 || white.rgba[p + 1] == 255 || white.rgba[p + 2] == 255);
    if (clipped > 0) std::printf("%s: the white reference clips: lower the exposure\n", args[k].c_str()), ++failures;
    long compared = 0;
    for (double c : sea.cover.cover) compared += c >= 0;
    if (compared < long(sea.cover.cover.size()) / 2) throw std::runtime_error(args[k] + ": foam is not brighter than the water");
    return sea;
}

// Per sea: its export, and its cover from the three pictures that follow it in `args`.
template <typename Check>
int for_each_sea(const std::vector<std::string>& args, Check check) {
    int failures = 0;
    for (std::size_t k = 0; k + 3 < args.size(); k += 4) {
        const Sea sea = load_sea(args, k, failures);
        failures += check(sea.dir, sea.e, sea.cover) ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}

// The faint foam: the cover capped at 0.15, as streakiness reads it.
constexpr double kFaint = 0.15;

int streaks(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        const double wind = number(e, "wind_speed"), ratio = streakiness(e, cover, 0.3, kFaint);
        const char* rule = wind >= 17.2 ? "Beaufort 8 and above, well-marked streaks: must be >= 2"
                         : wind < 13.9  ? "below Beaufort 7, no streaks: must be <= 1.3"
                                        : "Beaufort 7, streaks begin: not held";
        std::printf("%s: U = %4.1f m/s, the faint foam varies %.2f times more across the wind than along it (%s)\n",
                    dir.c_str(), wind, ratio, rule);
        // Correlation lengths, out to half the view (a length within it is measured, not just bounded).
        const double width = view_width(pinhole(e, cover.width, cover.height), cover.width, cover.height);
        const double along = correlation_length(e, cover, along_wind(e), kFaint, 0.1, width / 2);
        const double across = correlation_length(e, cover, across_wind(e), kFaint, 0.05, width / 2);
        const bool storm = wind >= 17.2;
        std::printf("  the faint foam's correlation length along the wind %.2f m, across it %.2f m (%.1f times; the view "
                    "%.0f m wide on the sea)%s\n",
                    along, across, along / across, width,
                    storm ? ": along >= 3 times across; narrow, across < 1.5 m" : "");
        const step06_test::StreakFigures lines =
            step06_test::measure_streaks(pinhole(e, cover.width, cover.height), cover.width, cover.height, cover.cover,
                                         along_wind(e), across_wind(e), width / (2 * std::sqrt(2.0)));
        std::printf("  %d lines (%.0f m of line on 1000 m^2), %.1f degrees from the wind; median length %.1f m, width "
                    "%.2f m, spacing %.1f m\n",
                    lines.lines, lines.metres_per_area, lines.angle_deg, lines.length_m, lines.width_m, lines.spacing_m);
        if (storm)
            std::printf("  as observers report them: >= 20 lines, within 20 degrees of the wind, a few metres apart (spacing "
                        ">= 3 m), narrow (width <= 1 m and <= a quarter of the spacing), long (>= 8 m)\n");
        const bool lengths = !storm || (along >= 3 * across && across < 1.5);
        const bool as_observed = !storm || (lines.lines >= 20 && lines.angle_deg <= 20 && lines.spacing_m >= 3 &&
                                            lines.width_m <= 1 && lines.width_m <= lines.spacing_m / 4 && lines.length_m >= 8);
        return (wind >= 17.2 ? ratio >= 2 : wind < 13.9 ? ratio <= 1.3 : true) && lengths && as_observed;
    });
}

int whitecaps(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        const double wind = number(e, "wind_speed"), seen = share_above(cover, kWhitecapCover);
        const double low = std::min(monahan(wind), callaghan(wind)), high = std::max(monahan(wind), callaghan(wind));
        const bool some = high >= 0.002;
        std::printf("%s: U = %4.1f m/s, whitecaps cover %6.2f %% of the picture; Monahan %5.2f %%, Callaghan %5.2f %% (%s)\n",
                    dir.c_str(), wind, 100 * seen, 100 * monahan(wind), 100 * callaghan(wind),
                    some ? "within half the lower, twice the higher" : "must be < 0.2 %");
        return some ? seen >= low / 2 && seen <= 2 * high : seen < 0.002;
    });
}

int stages(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        const double wind = number(e, "wind_speed"), all = share_above(cover, kWhitecapCover);
        const double active = share_above(cover, kActiveCover), split = all > 0 ? active / all : 0.0;
        const bool judged = all >= 0.002;
        std::printf("%s: U = %4.1f m/s, whitecaps W %6.2f %%, active W_A %6.2f %%: W_A/W %.3f (Monahan and Lu %.3f; %s)\n",
                    dir.c_str(), wind, 100 * all, 100 * active, split, kActiveShare,
                    judged ? "within a factor of 2" : "W < 0.2 %: not held");
        return !judged || (split >= kActiveShare / 2 && split <= 2 * kActiveShare);
    });
}

// Edges at least this soft (the 10 %-90 % rise's median, metres on the sea): a raft thins out over
// its last bubble cells, and the pattern's cells are about 0.9 m and 0.33 m.
constexpr double kMinEdgeRise = 0.3;
// Edges are hard where they rise within a pixel: at most this share of them.
constexpr double kMaxHardEdges = 0.25;

int edges(const std::vector<std::string>& args) {
    return for_each_sea(args, [](const std::string& dir, const Export& e, const FoamCover& cover) {
        const std::vector<Rise> rises = edge_rises(e, cover);
        std::vector<double> pixels, metres;
        for (const Rise& r : rises) pixels.push_back(r.pixels), metres.push_back(r.metres);
        const double hard = rises.empty() ? 0.0 : double(std::count_if(pixels.begin(), pixels.end(), [](double p) { return p <= 1; })) / double(rises.size());
        std::printf("%s: U = %4.1f m/s, %zu foam edges: 10-90 %% rise, median %.2f m (%.2f pixels); %.0f %% within one "
                    "pixel (must be >= %.2f m and < %.0f %%)\n",
                    dir.c_str(), number(e, "wind_speed"), rises.size(), median(metres), median(pixels), 100 * hard,
                    kMinEdgeRise, 100 * kMaxHardEdges);
        if (rises.size() < 20) return std::printf("  too few edges to judge\n"), true;
        return median(metres) >= kMinEdgeRise && hard < kMaxHardEdges;
    });
}

// Two cameras' pictures of the same sea agree on the ground both see: within this band of
// distances from each eye (metres), where a deck camera's pixels are stretched at most about five
// times along the view and the foam is not yet filtered away.
constexpr double kNearest = 5, kFarthest = 60;
// The ground points compared: a grid of this spacing (metres), so that both pictures are weighed
// by the sea's area, not by their pixels.
constexpr double kGroundStep = 0.25;

// The cover a camera records at a point of the sea; -1 where it does not see the point within the band.
double cover_seen(const Sea& sea, const Pinhole& camera, const glm::dvec3& point) {
    const double distance = glm::length(point - camera.eye);
    if (distance < kNearest || distance > kFarthest) return -1;
    const glm::ivec2 at = camera.pixel(point, sea.cover.width, sea.cover.height);
    return sea.cover.at(at.x, at.y);
}

// The whitecap patches (4-connected on the grid) among the ground points: `whitecap` per point
// of a columns x rows grid.
int patches(std::vector<char> whitecap, int columns, int rows) {
    int count = 0;
    for (int start = 0; start < columns * rows; ++start) {
        if (!whitecap[std::size_t(start)]) continue;
        ++count;
        std::vector<int> stack{start};
        whitecap[std::size_t(start)] = 0;
        while (!stack.empty()) {
            const int p = stack.back(), x = p % columns, y = p / columns;
            stack.pop_back();
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
                const int q = (y + dy) * columns + x + dx;
                if (x + dx < 0 || x + dx >= columns || y + dy < 0 || y + dy >= rows || !whitecap[std::size_t(q)]) continue;
                whitecap[std::size_t(q)] = 0;
                stack.push_back(q);
            }
        }
    }
    return count;
}

// The same sea at the same time from two cameras: the whitecap share each records over the ground
// both see (see the top of the file).
bool agree_on(const Sea& a, const Sea& b) {
    const Pinhole ca = pinhole(a.e, a.cover.width, a.cover.height), cb = pinhole(b.e, b.cover.width, b.cover.height);
    // The grid spans what a sees of the sea within the band.
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (int j = 0; j < a.cover.height; ++j)
        for (int i = 0; i < a.cover.width; ++i)
            if (const auto p = ca.ground(ca.ray(i, j, a.cover.width, a.cover.height)); p && glm::length(*p - ca.eye) <= kFarthest)
                lo = glm::min(lo, glm::dvec2(p->x, p->z)), hi = glm::max(hi, glm::dvec2(p->x, p->z));
    if (!(lo.x < hi.x)) throw std::runtime_error(a.dir + ": the camera sees no sea within the band");
    const int columns = int((hi.x - lo.x) / kGroundStep) + 1, rows = int((hi.y - lo.y) / kGroundStep) + 1;
    std::vector<char> white_a(std::size_t(columns) * rows, 0), white_b(white_a.size(), 0);
    long shared = 0, seen_a = 0, seen_b = 0;
    double light_a = 0, light_b = 0;  // the sums of the covers: the foam's light, which no pixel size changes
    // The same, by distance from b's eye (where they part, the foam a camera records depends on
    // how far it is).
    constexpr double kBands[] = {kNearest, 15, 30, kFarthest};
    double by_band[3][3] = {};  // points, a's summed cover, b's
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns; ++x) {
            const glm::dvec3 point(lo.x + x * kGroundStep, 0, lo.y + y * kGroundStep);
            const double cover_a = cover_seen(a, ca, point), cover_b = cover_seen(b, cb, point);
            if (cover_a < 0 || cover_b < 0) continue;
            ++shared;
            const std::size_t p = std::size_t(y) * columns + x;
            white_a[p] = cover_a > kWhitecapCover, white_b[p] = cover_b > kWhitecapCover;
            seen_a += white_a[p], seen_b += white_b[p];
            light_a += cover_a, light_b += cover_b;
            const double distance = glm::length(point - cb.eye);
            const int band = distance < kBands[1] ? 0 : distance < kBands[2] ? 1 : 2;
            by_band[band][0] += 1, by_band[band][1] += cover_a, by_band[band][2] += cover_b;
        }
    if (shared == 0) throw std::runtime_error(a.dir + " and " + b.dir + ": the two cameras see no sea in common");
    // What is held: the mean cover, the light the foam sends back over the same sea. A count above a
    // threshold is not: on lace, a fine pixel sees bright borders above it where a coarse one
    // averages the holes in below it (on this sea from 150 m and from 40 m, 1.0 % against 6.0 % at
    // 10 m/s), so two cameras at different distances count differently the same foam. The mean of
    // the cover is linear in the light and the same at any pixel size where the renderer filters
    // rightly: what it tests.
    const double wa = double(seen_a) / double(shared), wb = double(seen_b) / double(shared);
    const double la = light_a / double(shared), lb = light_b / double(shared), mean = (la + lb) / 2;
    const int na = patches(white_a, columns, rows), nb = patches(white_b, columns, rows);
    const double error = (na + nb) > 0 ? mean / std::sqrt((na + nb) / 2.0) : 0.0;  // a patch is one sample
    const double ratio = la > 0 ? lb / la : INFINITY;
    const bool judged = std::max(wa, wb) >= 0.002;
    const bool holds = !judged || (ratio >= 0.67 && ratio <= 1.5) || std::abs(la - lb) <= 3 * error;
    std::printf("%s and %s: U = %4.1f m/s, over %.0f m2 of sea both see (%g-%g m from each eye): mean foam cover "
                "%.4f and %.4f, ratio %.2f, difference %.2f standard errors over %d and %d patches (%s); whitecaps "
                "counted above %.2f: %.2f %% and %.2f %% (not held)\n",
                a.dir.c_str(), b.dir.c_str(), number(a.e, "wind_speed"), double(shared) * kGroundStep * kGroundStep, kNearest,
                kFarthest, la, lb, ratio, error > 0 ? std::abs(la - lb) / error : 0.0, na, nb,
                judged ? "must be within [0.67, 1.5] or 3 standard errors" : "both under 0.2 % whitecaps: not held",
                kWhitecapCover, 100 * wa, 100 * wb);
    std::printf("  by distance from the second eye:");
    for (int band = 0; band < 3; ++band)
        if (by_band[band][0] > 0)
            std::printf(" %g-%g m, mean cover %.4f and %.4f;", kBands[band], kBands[band + 1],
                        by_band[band][1] / by_band[band][0], by_band[band][2] / by_band[band][0]);
    std::printf("\n");
    return holds;
}

int agree(const std::vector<std::string>& args) {
    int failures = 0;
    for (std::size_t k = 0; k + 7 < args.size(); k += 8) {
        const Sea a = load_sea(args, k, failures), b = load_sea(args, k + 4, failures);
        if (number(a.e, "wind_speed") != number(b.e, "wind_speed") || a.e.time != b.e.time)
            throw std::runtime_error(a.dir + " and " + b.dir + " are not the same sea at the same time");
        failures += agree_on(a, b) ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
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
    const ocean::Image image = load_picture(path);
    const auto luma = [&](int x, int y) { return ocean_test::display_luma(image, x, y); };
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
        const std::map<std::string, int (*)(const std::vector<std::string>&)> per_sea{
            {"whitecaps", whitecaps}, {"stages", stages}, {"edges", edges}, {"streaks", streaks}};
        if (per_sea.count(mode) && argc >= 6 && (argc - 2) % 4 == 0) return per_sea.at(mode)(std::vector<std::string>(argv + 2, argv + argc));
        if (mode == "agree" && argc >= 10 && (argc - 2) % 8 == 0) return agree(std::vector<std::string>(argv + 2, argv + argc));
        if (mode == "detail" && argc == 5) return detail(argv[2], fraction(argv[3]), fraction(argv[4]));
        std::fprintf(stderr, "usage: picture_check glitter DIR IMAGE [DIR IMAGE]... | whitecaps|stages|edges|streaks DIR FOAM WATER "
                             "WHITE... | agree A_DIR A_FOAM A_WATER A_WHITE B_DIR B_FOAM B_WATER B_WHITE... | detail IMAGE FROM TO\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "picture_check: %s\n", e.what());
        return 2;
    }
}
