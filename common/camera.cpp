#include "common/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include <stdexcept>

namespace ocean {

void Camera::declare_params(ParamRegistry& params, const CameraView& view, double reach) {
    // The view is the default; the parameters are bound to the camera the steps draw from.
    mode = Orbit;
    target = glm::dvec3(view.target);
    distance = view.distance;
    yaw_deg = view.yaw_deg;
    pitch_deg = view.pitch_deg;
    const auto camera_group = params.group(kCameraGroup);
    params.add_choice("camera_mode", &mode, {"orbit", "fly"}, "orbit turns around the target; fly moves the eye (WASD, Q/E)");
    params.add_float("camera_yaw", &yaw_deg, -360, 360, "heading of the view, degrees (0 looks along -z)");
    params.add_float("camera_pitch", &pitch_deg, -89, 89, "how far the view looks down, degrees");
    params.add_float("camera_distance", &distance, 0.5f, 1000, "eye-to-target distance, metres").logarithmic();
    params.add_double("camera_target_x", &target.x, -reach, reach, "point looked at, x (metres)");
    params.add_float("camera_target_y", &target.y, -1000, 1000, "point looked at, y (metres, up)");
    params.add_double("camera_target_z", &target.z, -reach, reach, "point looked at, z (metres)");
    params.add_float("camera_fov", &fov_deg, 10, 120, "vertical field of view, degrees");
}

glm::vec3 Camera::forward() const {
    const float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
    return {std::cos(pitch) * std::sin(yaw), -std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

glm::dvec3 Camera::eye_world() const { return target - glm::dvec3(forward()) * double(distance); }

glm::vec3 Camera::eye() const { return glm::vec3(eye_world()); }

glm::mat4 Camera::view() const { return view(glm::dvec3(0.0)); }

glm::mat4 Camera::view(const glm::dvec3& origin) const {
    return glm::mat4(glm::lookAt(eye_world() - origin, target - origin, glm::dvec3(0, 1, 0)));
}

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_deg), std::max(aspect, 1e-3f), near_plane, far_plane);
}

std::optional<Ray> cursor_ray(const Camera& camera, float aspect, const glm::dvec3& origin, glm::dvec2 cursor,
                              glm::dvec2 window) {
    if (window.x <= 0 || window.y <= 0) return std::nullopt;
    // The cursor on the near and the far plane, from the origin: in float, as the frame draws.
    const glm::vec2 at(cursor), size(window);
    const glm::vec2 ndc(2 * at.x / size.x - 1, 1 - 2 * at.y / size.y);
    const glm::mat4 inverse = glm::inverse(camera.projection(aspect) * camera.view(origin));
    const glm::vec4 near = inverse * glm::vec4(ndc, -1, 1), far = inverse * glm::vec4(ndc, 1, 1);
    const glm::vec3 on_near = glm::vec3(near) / near.w, on_far = glm::vec3(far) / far.w;
    return Ray{origin + glm::dvec3(on_near), glm::normalize(glm::dvec3(on_far - on_near))};
}

void Camera::apply(const CameraInput& input, float dt) {
    const float degrees_per_pixel = 0.25f;
    const glm::dvec3 eye_before = eye_world();
    yaw_deg = std::fmod(yaw_deg + input.drag.x * degrees_per_pixel, 360.0f);
    pitch_deg = std::clamp(pitch_deg + input.drag.y * degrees_per_pixel, -89.0f, 89.0f);
    if (mode == Fly) {
        // Turning in fly mode keeps the eye where it is: move the target around it instead (in
        // double: 1000 km out, a float step of 8 m/s at 60 frames a second would round away).
        target = eye_before + glm::dvec3(forward()) * double(distance);
        const glm::vec3 f = forward();
        const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
        const float speed = (input.fast ? 40.0f : 8.0f) * dt;
        target += glm::dvec3((right * input.move.x + glm::vec3(0, 1, 0) * input.move.y + f * input.move.z) * speed);
    } else {
        distance = std::clamp(distance * std::pow(0.9f, input.scroll), 0.5f, 1000.0f);
    }
}

}  // namespace ocean

namespace ocean {

const std::vector<CameraPreset>& camera_presets() {
    static const std::vector<CameraPreset> presets{
        {"overview", "above the sea, looking down at the waves", {{0, 0, 0}, 70, 35, 28}},
        {"deck", "a ship's deck, 12 m up, the sea to the horizon", {{0, 0, 0}, 60, 35, 12}},
        {"low", "5 m above the water, level with the crests", {{0, 2, 0}, 30, 35, 7}},
        {"top", "straight down from 150 m: the pattern of the waves", {{0, 0, 0}, 150, 0, 89}},
    };
    return presets;
}

const CameraView& camera_view(const std::string& name) {
    for (const auto& preset : camera_presets())
        if (name == preset.name) return preset.view;
    throw std::out_of_range("no camera preset '" + name + "'");
}

std::optional<std::string> apply_camera_preset(ParamRegistry& params, const std::string& name) {
    std::string names;
    for (const auto& preset : camera_presets()) {
        names += (names.empty() ? "" : "|") + std::string(preset.name);
        if (name != preset.name) continue;
        if (params.find("camera_yaw") == nullptr) return std::string("--camera: this step has no camera");
        const auto number = [](float v) { return std::to_string(v); };
        for (const auto& [key, value] :
             std::vector<std::pair<std::string, std::string>>{{"camera_target_x", number(preset.view.target.x)},
                                                              {"camera_target_y", number(preset.view.target.y)},
                                                              {"camera_target_z", number(preset.view.target.z)},
                                                              {"camera_distance", number(preset.view.distance)},
                                                              {"camera_yaw", number(preset.view.yaw_deg)},
                                                              {"camera_pitch", number(preset.view.pitch_deg)},
                                                              {"camera_mode", "orbit"}})
            if (auto error = params.set(key, value)) return error;
        return std::nullopt;
    }
    return "--camera expects one of " + names + ", got '" + name.substr(0, 40) + "'";
}

}  // namespace ocean
