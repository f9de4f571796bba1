// What the checks of a rendered picture share (step06's picture_check, step08's wake_check): the
// picture as loaded, its pixels' brightness, and the camera that took it, a pinhole rebuilt from
// the parameters its --export wrote (yaw, pitch, distance to the target, vertical field of view,
// as --list-params describes them). Like export_reader.hpp, it knows no shader and no spectrum.
#pragma once

#include "common/image.hpp"
#include "tests/export_reader.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace ocean_test {

inline double radians(double degrees) { return degrees * 3.14159265358979323846 / 180; }

inline double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// A pixel's luminance in linear light (the picture's sRGB values undone), 0 to 1.
inline double luminance(const std::uint8_t* rgba) {
    return 0.2126 * srgb_to_linear(rgba[0] / 255.0) + 0.7152 * srgb_to_linear(rgba[1] / 255.0) +
           0.0722 * srgb_to_linear(rgba[2] / 255.0);
}

// Pixel (x, y)'s luma in display values (0 to 255), as the eye compares two pictures.
inline double display_luma(const ocean::Image& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

inline ocean::Image load_picture(const std::string& path) {
    std::string error;
    auto image = ocean::load_image(path, &error);
    if (!image) throw std::runtime_error(error);
    return *image;
}

// The camera's pinhole, from its parameters. Positions in the picture are in pixels from its top
// left corner, continuous: pixel (i, j) (row 0 at the top) spans [i, i + 1] x [j, j + 1].
struct Pinhole {
    glm::dvec3 eye, forward, right, up;
    double tan_half_fov, aspect;
    glm::dvec3 ray_through(glm::dvec2 at, int width, int height) const {
        const double x = (2 * at.x / width - 1) * tan_half_fov * aspect, y = (1 - 2 * at.y / height) * tan_half_fov;
        return glm::normalize(forward + x * right + y * up);
    }
    // The ray through the centre of pixel (i, j).
    glm::dvec3 ray(int i, int j, int width, int height) const { return ray_through({i + 0.5, j + 0.5}, width, height); }
    // Where a point of the world falls in the picture: ray_through's inverse ((-1, -1) behind the eye).
    glm::dvec2 position(const glm::dvec3& point, int width, int height) const {
        const glm::dvec3 d = point - eye;
        const double depth = glm::dot(d, forward);
        if (depth <= 0) return {-1, -1};
        const double x = glm::dot(d, right) / depth / (tan_half_fov * aspect), y = glm::dot(d, up) / depth / tan_half_fov;
        return {(x + 1) / 2 * width, (1 - y) / 2 * height};
    }
    // The pixel (column, row) a point of the world falls in.
    glm::ivec2 pixel(const glm::dvec3& point, int width, int height) const {
        const glm::dvec2 at = position(point, width, height);
        return {int(std::floor(at.x)), int(std::floor(at.y))};
    }
    // Where a ray from the eye meets the sea's mean level (y = 0); none at or above the horizon.
    std::optional<glm::dvec3> ground(const glm::dvec3& ray) const {
        if (ray.y >= -1e-3) return std::nullopt;
        return eye + ray * (-eye.y / ray.y);
    }
};

// The pinhole of the camera whose --export is `e`, for a picture of width x height pixels.
inline Pinhole pinhole(const Export& e, int width, int height) {
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

}  // namespace ocean_test
