// Chapter 8: the boat and the stones, as the program runs them: a pressure patch the shape of a
// hull's waterline sailing at the boat's speed and heading, and stones dropped where the learner
// clicks, pushing on a wave field that follows the boat. The tests and the README's figures drive
// the same class, so what they measure is what the window shows.
#pragma once

#include "step08_wakes/wave_field.hpp"

#include <glm/vec2.hpp>

#include <functional>

namespace step08 {

struct BoatSettings {
    double speed = 4;     // m/s
    double length = 6;    // m, at the waterline; the beam is a third of it
    double draft = 0.4;   // m: the hull pushes on the water with rho g draft at its middle
    double turn_rate = 20;  // degrees a second with the rudder hard over
};

// A stone, as a click drops it: an impulse (the integral of p / rho over the splash's time and
// area, m^4/s: its momentum over the water's density) spread as a Gaussian of kStoneRadius, one
// cell of the default grid (a narrower splash would be waves shorter than the grid holds). The
// default is a 200 kg boulder at 10 m/s (dropped from 5 m): 2000 kg m/s over 1000 kg/m^3, the
// smallest that the default camera shows in the program's 6 m/s breeze: its splash is steeper than a wave
// can stand, and foams, within the first second, and its rings are linear waves a few
// centimetres high (how_we_know.md).
inline constexpr double kStoneImpulse = 2;   // m^4/s
inline constexpr double kStoneRadius = 0.5;  // m

// Where the patch's pressure is: p / rho = g draft exp(-(a^2 / (2 (L/4)^2) + b^2 / (2 (B/4)^2)))
// at a metres along the hull from its middle and b across, so 86 % of it lies within the waterline
// (L long, B = L / 3 wide).
double hull_pressure(const BoatSettings& boat, glm::dvec2 along_across);

// The patch of a hull `length` metres long (at the waterline) that displaces `submerged_volume` m^3
// of water: the depression the patch alone would hold, g draft times the Gaussian's area
// 2 pi (L/4) (L/12) over g, is that volume, so draft = 24 V / (pi L^2). For step07's boat, whose
// submerged volume its buoyancy already gives.
BoatSettings hull_of(double length, double submerged_volume);

// One step of the field of h seconds, the hull's pressure already in `forcing`, covering the share
// `from` to `to` of the interval press() was given. A program that moves something else with the
// field in the same steps (a body floating on it) takes the step in its place; by default it is
// field.step(h, forcing).
using FieldStep = std::function<void(WaveField& field, double h, Forcing& forcing, double from, double to)>;

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
    // in which it moves at most a cell, as sail() is; each step is `step`'s, if given.
    void press(double seconds, glm::dvec2 to, glm::dvec2 heading, const BoatSettings& hull,
               const FieldStep& step = {});
    // A stone's splash at `at` (x, z): an impulse of `impulse` m^4/s (its momentum over the
    // water's density) spread over `radius` metres. Outside the grid it pushes on nothing.
    void drop_stone(glm::dvec2 at, double impulse = kStoneImpulse, double radius = kStoneRadius);

    const WaveField& field() const { return field_; }
    WaveField& field() { return field_; }  // for a program that sets parts of it (a calm patch)
    glm::dvec2 boat_position() const { return position_; }
    glm::dvec2 boat_heading() const;  // unit (x, z)

private:
    // One step of h seconds with the patch at `middle`, heading `ahead` (unit); the grid's centre a
    // quarter of its side behind it, so that most of the grid holds the wake.
    // The step covers the share `from` to `to` of press()'s interval (step's, if given).
    void press_once(double h, glm::dvec2 middle, glm::dvec2 ahead, const BoatSettings& hull,
                    const FieldStep& step = {}, double from = 0, double to = 1);

    WaveField field_;
    Forcing forcing_;
    glm::dvec2 position_{0.0};
    double heading_ = 0;  // radians from +x towards +z
};

}  // namespace step08
