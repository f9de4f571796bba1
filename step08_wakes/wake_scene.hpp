// Chapter 8.5: the boat and the stones, as the program runs them: a pressure patch the shape of a
// hull's waterline sailing at the boat's speed and heading, and stones dropped where the learner
// clicks, pushing on a wave field that follows the boat. The tests and the README's figures drive
// the same class, so what they measure is what the window shows.
#pragma once

#include "step07_buoyancy/floating_body.hpp"
#include "step08_wakes/radiating_buoy.hpp"
#include "step08_wakes/wave_field.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step08 {

struct BoatSettings {
    double speed = 4;     // m/s
    double length = 6;    // m, at the waterline; the beam is a third of it
    double draft = 0.4;   // m: the hull pushes on the water with rho g draft at its middle
    double turn_rate = 20;  // degrees a second with the rudder hard over
};

// Where the patch's pressure is: p / rho = g draft exp(-(a^2 / (2 (L/4)^2) + b^2 / (2 (B/4)^2)))
// at a metres along the hull from its middle and b across, so 86 % of it lies within the waterline
// (L long, B = L / 3 wide).
double hull_pressure(const BoatSettings& boat, glm::dvec2 along_across);

// The patch of a hull `length` metres long (at the waterline) that displaces `submerged_volume` m^3
// of water: the depression the patch alone would hold, g draft times the Gaussian's area
// 2 pi (L/4) (L/12) over g, is that volume, so draft = 24 V / (pi L^2). For step07's boat, whose
// submerged volume its buoyancy already gives.
BoatSettings hull_of(double length, double submerged_volume);

// A buoy and its sources (radiating_buoy.hpp).
struct Radiating {
    step07::FloatingBody* body = nullptr;
    RadiatingBuoy* sources = nullptr;
};

// step07's bodies a press carries along in its steps, in contact with the field (hull_contact.hpp)
// or radiating into it (radiating_buoy.hpp): each step moves them with the field, over the part of
// the frame it covers.
struct BodiesInContact {
    std::vector<step07::FloatingBody*> bodies;  // such as the contact takes (can_touch)
    const step07::Surface* before = nullptr;   // the incident sea at the frame's start and end
    const step07::Surface* now = nullptr;
    double sea_interval = 0;                   // seconds between those two seas
    std::vector<Radiating> radiating;          // such as their sources hold for (RadiatingBuoy::holds)
};

class WakeScene {
public:
    explicit WakeScene(const WaveFieldSettings& field);

    // `seconds` of sailing: the boat moves on (turning at `rudder` times its turn rate, -1 to 1;
    // positive to starboard, its right), the grid follows it, the field is stepped with the boat's
    // pressure. Cut into steps in which the boat moves at most a cell, so its patch slides
    // smoothly over the grid.
    void sail(double seconds, const BoatSettings& boat, double rudder);
    // The boat put at `position` (x, z), heading along `heading` (x, z; any length), the grid
    // following it; the field is left as it is.
    void place(glm::dvec2 position, glm::dvec2 heading);
    // A hull the program moves itself (step08's main: step07's boat, pushed by its engine): over
    // `seconds` its middle goes on from where it was to `to` (x, z) and its heading turns to
    // `heading` (x, z), pressing with `hull`'s patch (its speed and turn rate unused). Cut into steps
    // in which it moves at most a cell, as sail() is; `bodies`, if given, are moved in the same
    // steps, in contact with the field.
    void press(double seconds, glm::dvec2 to, glm::dvec2 heading, const BoatSettings& hull,
               const BodiesInContact* bodies = nullptr);
    // A stone's splash at `at` (x, z): an impulse of `impulse` m^4/s (its momentum over the
    // water's density) spread over `radius` metres.
    void drop_stone(glm::dvec2 at, double impulse = 0.02, double radius = 0.3);

    // The field at rest under a body floating still (hull_contact.hpp's settle_under), for a body
    // that comes into contact with it.
    void settle_under(const step07::FloatingBody& body, const step07::Surface& sea);
    // Its dent taken out again, for a body that leaves contact (hull_contact.hpp's lift_out).
    void lift_out(const step07::FloatingBody& body, const step07::Surface& sea);

    const WaveField& field() const { return field_; }
    glm::dvec2 boat_position() const { return position_; }
    glm::dvec2 boat_heading() const;  // unit (x, z)

private:
    // One step of h seconds with the patch at `middle`, heading `ahead` (unit); the grid's centre a
    // quarter of its side behind it, so that most of the grid holds the wake.
    // With `bodies`, the step covers the share `from` to `to` of their frame.
    void press_once(double h, glm::dvec2 middle, glm::dvec2 ahead, const BoatSettings& hull,
                    const BodiesInContact* bodies = nullptr, double from = 0, double to = 1);

    WaveField field_;
    Forcing forcing_;
    glm::dvec2 position_{0.0};
    double heading_ = 0;  // radians from +x towards +z
};

}  // namespace step08
