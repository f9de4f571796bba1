#include "step07_buoyancy/bodies.hpp"

#include "common/constants.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace step07 {

std::array<BodySettings, 3> body_settings(const BodyParams& params) {
    std::array<BodySettings, 3> s;
    s[kBuoy].shape = {ShapeKind::Sphere, glm::dvec3(params.buoy_diameter)};
    s[kBuoy].density = params.buoy_density;
    s[kRaft].shape = {ShapeKind::Box, {params.raft_size, 0.4, params.raft_size}};
    s[kRaft].density = params.raft_density;
    const double length = params.boat_length;
    s[kBoat].shape = {ShapeKind::Hull, {length, length / 6, length / 3}};  // (length, depth, beam)
    s[kBoat].density = params.boat_density;
    for (BodySettings& body : s) {
        body.linear_drag = params.drag;
        body.cells_per_side = 6;
    }
    s[kBoat].cells_per_side = 8;                                  // the hull's shape needs a finer grid
    s[kBoat].ballast = {0, -0.25 * s[kBoat].shape.size.y, 0};  // an engine and a keel: upright
    return s;
}

std::vector<FloatingBody> drop_bodies(const BodyParams& params, glm::dvec3 eye, glm::dvec2 ahead) {
    const glm::dvec2 side(-ahead.y, ahead.x);  // to the right of the view
    const auto spot = [&](double forward, double across) {
        const glm::dvec2 p = glm::dvec2(eye.x, eye.z) + forward * ahead + across * side;
        return glm::dvec3(p.x, params.drop_height, p.y);
    };
    const std::array<BodySettings, 3> s = body_settings(params);
    const double heading = std::atan2(ahead.y, ahead.x);
    std::vector<FloatingBody> bodies;
    bodies.reserve(3);
    bodies.emplace_back(s[kBuoy], spot(14, 1));
    bodies.emplace_back(s[kRaft], spot(26, 5), glm::angleAxis(0.4, glm::dvec3(0, 1, 0)));
    bodies.emplace_back(s[kBoat], spot(22, 12), glm::angleAxis(-heading + 1.1, glm::dvec3(0, 1, 0)));
    return bodies;
}

std::vector<FloatingBody> drop_bodies(const BodyParams& params, const ocean::Camera& camera) {
    const glm::vec3 f = camera.forward();
    const glm::dvec2 ahead = glm::normalize(glm::dvec2(f.x, f.z) + glm::dvec2(1e-9, 0));
    return drop_bodies(params, camera.eye_world(), ahead);
}

// The thrust accelerates the boat against its drag (0.5/s of the water it displaces, about its own
// mass afloat); the turning force acts at half a length behind the middle.
void steer(FloatingBody& boat, double throttle, double rudder) {
    const double weight = boat.mass() * ocean::kGravity;
    const double thrust = kFullThrust * std::clamp(throttle, -1.0, 1.0);
    const double turn = kFullRudder * std::clamp(rudder, -1.0, 1.0);
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    const glm::dvec3 across = boat.orientation() * glm::dvec3(0, 0, 1);  // to starboard (its right)
    boat.add_force(thrust * weight * along, {0, 0, 0});
    // A rudder turned to starboard pushes the stern to port, which swings the bow to starboard.
    boat.add_force(-turn * weight * across, {-0.5 * boat.settings().shape.size.x, 0, 0});
}

Arrows held_arrows() {
    if (ImGui::GetIO().WantCaptureKeyboard) return {};
    return {double(ImGui::IsKeyDown(GLFW_KEY_UP)) - double(ImGui::IsKeyDown(GLFW_KEY_DOWN)),
            double(ImGui::IsKeyDown(GLFW_KEY_RIGHT)) - double(ImGui::IsKeyDown(GLFW_KEY_LEFT))};
}

void steer(FloatingBody& boat, const Steering& panel, const Arrows& arrows) {
    steer(boat, double(panel.throttle) + arrows.throttle, double(panel.rudder) + arrows.rudder);
}

// 6 m at most: the 9 m boat gets 7.6 m/s, not 11; 3 m at least: the 1.2 m buoy gets 3.8 m/s,
// which a learner sees from 14 m away.
double push_speed(const FloatingBody& body) {
    const glm::dvec3 size = body.settings().shape.size;
    const double d = std::clamp(std::max(size.x, size.z), 3.0, 6.0);
    const double c = body.settings().linear_drag;
    return c > 1e-6 ? d * c / (1 - std::exp(-c)) : d;
}

void advance_bodies(std::vector<FloatingBody>& bodies, const Surface& before, const Surface& now, double dt,
                    double sea_interval) {
    const double step = std::min(dt, kMaxBodyFrame);
    for (FloatingBody& body : bodies) body.step(before, now, step, sea_interval);
}

}  // namespace step07
