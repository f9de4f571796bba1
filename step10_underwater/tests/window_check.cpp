// window_check: Snell's window measured from a picture, knowing nothing of the shaders.
//
//   window_check PICTURE.png PITCH_DEGREES [VERTICAL_FOV_DEGREES]
//
// The picture: a flat sea seen from below by a camera looking up PITCH degrees above the horizontal
// (step10's camera_pitch is minus that), whose vertical field of view is VERTICAL_FOV (50). Down
// the picture's middle column each row is a direction whose angle from the vertical the camera's
// projection gives: elevation = pitch + atan(ndc_y tan(fov / 2)). Inside Snell's window the sky
// shines through; outside it the surface mirrors the darker depths. The window's edge is where the
// light falls fastest, between 40 and 60 degrees: Fresnel's transmission falls to zero at the
// critical angle as a square root does, steepest right there. It must lie at asin(1 / 1.333) =
// 48.59 degrees from the vertical within 0.5 degree, and outside must be darker than inside.
// Prints the figures; exit 0 when they hold, 1 otherwise, 2 on bad input.
#include "common/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWaterIndex = 1.333;

double luminance(const ocean::Image& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::fprintf(stderr, "usage: window_check PICTURE.png PITCH_DEGREES [VERTICAL_FOV_DEGREES]\n");
        return 2;
    }
    std::string error;
    const auto image = ocean::load_image(argv[1], &error);
    if (!image) {
        std::fprintf(stderr, "window_check: %s\n", error.c_str());
        return 2;
    }
    const double pitch = std::atof(argv[2]) * kPi / 180, half_fov = (argc == 4 ? std::atof(argv[3]) : 50.0) * kPi / 360;
    // Row y (0 at the top) looks this far from the vertical.
    const auto from_vertical = [&](double y) {
        const double ndc = 1 - 2 * (y + 0.5) / image->height;
        return 90 - (pitch + std::atan(ndc * std::tan(half_fov))) * 180 / kPi;
    };
    const int x = image->width / 2;
    std::vector<double> inside, outside;
    for (int y = 0; y < image->height; ++y) {
        const double angle = from_vertical(y);
        if (angle < 42) inside.push_back(luminance(*image, x, y));
        if (angle > 55) outside.push_back(luminance(*image, x, y));
    }
    if (inside.size() < 5 || outside.size() < 5) {
        std::fprintf(stderr, "window_check: the picture does not show both sides of 48.6 degrees (pitch, fov?)\n");
        return 2;
    }
    const double bright = median(inside), dark = median(outside);
    // The steepest fall from one row to the next, its place refined by a parabola through the
    // three falls around it.
    std::vector<double> fall(std::size_t(image->height), 0.0);
    int steepest = -1;
    for (int y = 1; y < image->height; ++y) {
        const double angle = from_vertical(y - 0.5);
        if (angle < 40 || angle > 60) continue;
        fall[std::size_t(y)] = luminance(*image, x, y - 1) - luminance(*image, x, y);
        if (steepest < 0 || fall[std::size_t(y)] > fall[std::size_t(steepest)]) steepest = y;
    }
    double edge = -1;
    if (steepest > 1 && steepest + 1 < image->height) {
        const double a = fall[std::size_t(steepest - 1)], b = fall[std::size_t(steepest)], c = fall[std::size_t(steepest + 1)];
        const double shift = (a - 2 * b + c) != 0 ? 0.5 * (a - c) / (a - 2 * b + c) : 0.0;
        edge = from_vertical(steepest - 0.5 + std::clamp(shift, -0.5, 0.5));
    }
    const double critical = std::asin(1 / kWaterIndex) * 180 / kPi;
    std::printf("window_check: inside %.1f, outside %.1f (of 255); edge at %.2f deg from the vertical, "
                "Snell's %.2f (limit 0.5)\n", bright, dark, edge, critical);
    const bool ok = edge > 0 && std::abs(edge - critical) <= 0.5 && dark < bright;
    if (!ok) std::printf("FAIL: %s\n", edge < 0 ? "no edge found" : "the window is not Snell's");
    return ok ? 0 : 1;
}
