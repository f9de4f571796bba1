// One camera, two ways to drive it. Its state is a target point, a distance and two angles;
// orbit mode turns the eye around the target, fly mode turns the view around the eye and moves
// both. Because both modes share that state, switching keeps the view, and the state is four
// parameters that --set, presets and screenshots can reproduce.
#pragma once

#include "common/params.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace ocean {

struct CameraInput {
    glm::vec2 drag{0.0f};     // pixels the mouse moved with the left button down
    float scroll = 0;         // wheel steps
    glm::vec3 move{0.0f};     // fly: right, up, forward in [-1, 1]
    bool fast = false;        // shift held
};

// Where a camera looks from: the orbit camera's target, distance and angles.
// The panel group of the camera_* parameters (Previous/Next carry it to the next step).
inline const std::string kCameraGroup = "camera";

struct CameraView {
    glm::vec3 target;
    float distance, yaw_deg, pitch_deg;
};

// How far from the origin the camera may go, metres: a tile of sea around the origin, or an ocean
// crossed (a step that renders relative to the camera, as step06 does, can take 1000 km and more).
constexpr double kNearReach = 1e4, kOceanReach = 2e6;

class Camera {
public:
    enum Mode { Orbit = 0, Fly = 1 };

    // Declares camera_* parameters; the step chooses the defaults of its view, and how far it
    // may go (camera_target_x and _z within +-reach).
    void declare_params(ParamRegistry& params, const CameraView& view, double reach = kNearReach);

    void apply(const CameraInput& input, float dt);
    glm::vec3 eye() const;        // in float: enough within kNearReach
    glm::dvec3 eye_world() const; // in double: anywhere
    glm::vec3 forward() const;  // unit vector from the eye to the target
    glm::mat4 view() const;
    // The view with `origin` as the world's zero (camera-relative rendering): built in double, so
    // far from the origin the matrix keeps the precision that world coordinates in float lose.
    glm::mat4 view(const glm::dvec3& origin) const;
    glm::mat4 projection(float aspect) const;

    int mode = Orbit;
    glm::dvec3 target{0.0};  // double: 1000 km out, float's steps are 6 cm
    float distance = 10, yaw_deg = 0, pitch_deg = 20, fov_deg = 50;
    float near_plane = 0.1f, far_plane = 2000.0f;
};

// A ray in world metres: where it starts, and its direction (a unit vector).
struct Ray {
    glm::dvec3 from, direction;
};

// The ray under the cursor: through `cursor` (pixels from the window's top left, in a window
// `window` wide and high in the same units), from the near plane away from the eye, built from the
// matrices a camera-relative frame draws with (projection(aspect) * view(origin)), so that it meets
// what the window shows there, anywhere on an ocean. None for a window of no size.
std::optional<Ray> cursor_ray(const Camera& camera, float aspect, const glm::dvec3& origin, glm::dvec2 cursor,
                              glm::dvec2 window);

// Named views shared by every 3D step (--camera NAME), so that pictures of different chapters line
// up: they set the camera_* parameters.
struct CameraPreset {
    const char* name;
    const char* description;
    CameraView view;
};
// The views the 3D steps share (--camera NAME): overview, deck, low, top. A step starts from one
// of them (App::use_camera(camera_view("deck"))), so screenshots of neighbouring steps line up.
const std::vector<CameraPreset>& camera_presets();
const CameraView& camera_view(const std::string& name);  // throws std::out_of_range if unknown
// Sets the camera_* parameters to the preset's values, or returns a one-line error.
std::optional<std::string> apply_camera_preset(ParamRegistry& params, const std::string& name);

}  // namespace ocean
