// Chapter 9, the contact in the program: a body of step07's in contact with the wave field. Each step the body
// moves without the water's buoyancy (its drag stays); the field then finds the push under its hull
// that leaves the water there where the hull ends the step (contact_step.hpp), and
// that push moves the body. At rest it is the hydrostatic pressure, g times the hull's depth under
// the sea (Archimedes again); heaving, it is more or less than that by the waves the hull makes,
// which carry its energy away. The sea's own waves stay step07's: the contact's target is the hull
// less the sea's height, so the field holds only what the bodies add.
//
// For a flat-bottomed hull (step07's raft), whose pressure acts close to the surface as the
// field's does. The boat presses with its weight's patch instead (step08's wake_scene.hpp), and the
// buoy, a sphere, radiates through sources on its hull (radiating_buoy.hpp).
#pragma once

#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_surface.hpp"
#include "step09_radiation/contact_step.hpp"

#include <vector>

namespace step09 {

// Whether every point of a body lies in the field's inner part, clear of the absorbing layer:
// there the waves it makes are the field's to carry (in the layer they would be damped under it).
bool within_field(const WaveField& field, const step07::FloatingBody& body);

// Whether a body's bottom faces the water: tilted less than kMaxContactTilt from level. The
// contact reads and pushes the water under the bottom's points, about one a cell as the field sees
// them from above; a bottom tilted further (a raft tossed on its side) crowds them, and the
// contact's system grows singular (with random yaws and tilts up to 60 degrees it never did; past
// 75 it did). A body tilted further floats on step07's Archimedes until it rights itself.
constexpr double kMaxContactTilt = 45;  // degrees
bool level_enough(const step07::FloatingBody& body);

// Whether the contact takes a body now: a box (step07's raft), within the field's inner part,
// level enough, and with at most kMaxContactPoints points under its bottom. The contact's system
// grows as the cube of its points: 100 for the default raft take about 2 ms a step; a 10 m raft
// on 25 cm cells, 1600 points, made each frame take 0.7 s. A body it does not take floats on
// Archimedes.
constexpr std::size_t kMaxContactPoints = 400;
bool can_touch(const WaveField& field, const step07::FloatingBody& body);

// A body's side of a contact: the points on its bottom where it is below the water, and the arms
// from its centre of mass to them (world axes).
struct HullInContact {
    Contact contact;
    std::vector<glm::dvec3> arms;
};

// The points on a box's bottom face, about one a field cell: a grid of round(side / cell) points
// along each of its horizontal sides, the side's length as the field sees it from above (shorter
// when the box tilts), each at the middle of its share of the face (body frame, from the centre
// of mass).
std::vector<glm::dvec3> bottom_points(const step07::FloatingBody& body, double cell);

// The contact of a box-shaped body that has just moved `h` seconds without the water's buoyancy:
// the points of its bottom below the water (the incident sea `sea` at the step's end plus the
// field before it, read bilinearly), each with its target (its height less the sea's: what the
// field must reach there) and the compliance from the body's mass and inertia per unit density,
// travel (1 / m + (r_i x y) . I^-1 (r_j x y)), travel from FloatingBody::travel_per_acceleration.
HullInContact hull_contact(const WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea, double h);

// The pushes the field found (force / rho, one a contact point) moving the body over the step:
// rho Q up at each point, and their torques.
void push_hull(step07::FloatingBody& body, const HullInContact& hull, const std::vector<double>& pushes, double h);

// The field at rest under a body floating still: the dent a steady push holds, read at each of
// its bottom's points where that point is (less the sea's height); the potential untouched. A
// body put on a flat field instead would have to push its whole dent in at once.
void settle_under(WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea);

// The other way: the dent of a body floating still taken out of the field, for a body that leaves
// it (outside the field's inner part its waves are no longer the field's); the field's waves stay.
void lift_out(WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea);

// One step of h seconds of the field with bodies in contact: each body moves without the water's
// buoyancy over the sea going from `from` to `to` (sea_interval: the seconds between them, for the
// water's velocity), the field steps with their contacts (one system: the bodies move apart, so
// their compliances are blocks) and `forcing`, and each body is pushed. The bodies are given
// such as the contact takes (can_touch).
// `contact` keeps the field's kernel from step to step, and the pressure it held (for drawing).
void step_with_bodies(WaveField& field, ContactStep& contact, const std::vector<step07::FloatingBody*>& bodies,
                      const step07::Surface& from, const step07::Surface& to, double h, double sea_interval,
                      const Forcing& forcing = {});

// Two surfaces' blend, `share` of the way from `from` to `to`: the sea at a moment within a frame,
// for a body stepped in parts of it.
class SeaBetween : public step07::Surface {
public:
    SeaBetween(const step07::Surface& from, const step07::Surface& to, double share) : from_(from), to_(to), share_(share) {}
    step07::SurfaceAt at(glm::dvec2 rest) const override;
    glm::dvec3 displacement_below(glm::dvec2 rest, double depth) const override;

private:
    const step07::Surface &from_, &to_;
    double share_;
};

}  // namespace step09
