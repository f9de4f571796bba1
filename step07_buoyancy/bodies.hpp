// The chapter's three bodies (a buoy, a raft, a boat) and what a learner does to them in the
// window: where they are dropped, how the arrows steer the boat and how hard a right click pushes.
// main.cpp calls these each frame; the tests and the README's figure (./ocean figures) call the
// same functions on a flat sea, so the numbers the README quotes are the program's.
#pragma once

#include "common/camera.hpp"
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/floating_body.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace step07 {

enum BodyIndex { kBuoy = 0, kRaft = 1, kBoat = 2 };
inline constexpr std::array<const char*, 3> kBodyNames = {"buoy", "raft", "boat"};

// The three bodies' settings (shape, density, drag, cells, the boat's ballast) from the panel's.
std::array<BodySettings, 3> body_settings(const BodyParams& params);

// The three bodies dropped at params.drop_height in front of a camera at `eye` looking along
// `ahead` (a horizontal unit vector): all in the right part of the view, which the panel (at the
// left) leaves free; the boat broadside, so its length shows.
std::vector<FloatingBody> drop_bodies(const BodyParams& params, glm::dvec3 eye, glm::dvec2 ahead);
// The same in front of `camera`: at its eye, looking along its view turned level.
std::vector<FloatingBody> drop_bodies(const BodyParams& params, const ocean::Camera& camera);

// The boat's engine and rudder at full (the throttle or the rudder at 1, or an arrow held), as
// fractions of its weight m g: a thrust along its length at its middle, and a rudder's sideways
// force at its stern, sized for a change a learner sees within a second at the defaults (9 m boat,
// drag c = 0.5/s). Afloat, the boat displaces its own mass of water, so the hull's drag is about
// m c v: a thrust k m g reaches k g / c and covers k g (1 - (1 - e^-c) / c) / c = 0.43 k g metres
// in the first second. k = 0.4 (a fast motor boat's thrust to weight): 1.7 m in the first second,
// 7 m/s after five. The rudder's force r m g at the stern turns the boat against the yaw inertia
// m (L^2 + B^2) / 12 and the drag of the hull's cells: r = 0.1 turns it 16 degrees in the first
// second. tests/test_bodies.cpp holds FloatingBody on a flat sea to these numbers.
inline constexpr double kFullThrust = 0.4, kFullRudder = 0.1;

// Applies this frame's steering to the boat: `throttle` and `rudder` from -1 to 1 (the panel's
// plus the arrows' while they are held, clamped to that range); a positive rudder turns it to
// starboard (its right: the right arrow).
void steer(FloatingBody& boat, double throttle, double rudder);

// The arrows held this frame, as the boat's controls: up and down a throttle of 1 and -1, right
// and left a rudder of 1 and -1. None while the panel takes the keys (a field being typed in), and
// none headless. Read once a frame, in update().
struct Arrows {
    double throttle = 0, rudder = 0;
};
Arrows held_arrows();

// steer() with the panel's throttle and rudder plus the arrows held.
void steer(FloatingBody& boat, const Steering& panel, const Arrows& arrows);

// The speed a right click gives `body`: enough to carry it about its own size d (its longer
// horizontal side, between 3 and 6 m) in the first second against its linear drag c, on a flat
// sea: a speed v covers v (1 - e^-c) / c in a second, so v = d c / (1 - e^-c).
double push_speed(const FloatingBody& body);

// The longest time the bodies advance in one frame, in seconds. A longer frame is a stall, not a
// slow machine (auto's backend trial, a window being dragged, a shader rebuilt after an edit): the
// bodies advance only this far, so the arrows read at the stall's end do not push for the whole
// stall, and the next frame does not pay for a stall's worth of substeps (kMaxSubstep each, which
// would make it a stall too). 0.5 s: a machine drawing 2 frames a second still runs at real speed.
inline constexpr double kMaxBodyFrame = 0.5;

// Advances every body one frame of `dt` seconds (at most kMaxBodyFrame), the sea moving from
// `before` to `now` over it (FloatingBody::step).
void advance_bodies(std::vector<FloatingBody>& bodies, const Surface& before, const Surface& now, double dt,
                    double sea_interval);

}  // namespace step07
