// Chapter 7.7-7.12: a rigid body on the sea. Its hull is cut into small cells; each frame the sea
// is queried under every cell (sea_query.hpp), and each substep adds up, cell by cell,
//   buoyancy   rho_w g V_submerged, up, on the cell's vertical            (Archimedes)
//   drag       -rho_w V_submerged c (v_cell - v_water)                    (linear, against the water's own
//   motion)
// and their torques about the centre of mass, then moves the body by semi-implicit Euler.
//
// A cell's submerged share is its vertical extent below the water line (the cell treated as a
// slab, tilted with the body): exact for an upright box, whose cells are layers. A sphere needs
// no cells: its submerged volume is the spherical cap under the water line at its centre, exactly,
// and its buoyancy and drag act through its centre (hull_forces.hpp), as on a real uniform sphere.
// The water's velocity for the drag shrinks with depth (sea_query.hpp's water_velocity).
// There is no added mass (the water a body must accelerate with it when it heaves): a box's heave
// period is 2 pi sqrt(d / g) for draft d. For the tested box that water is of the order of the box's
// own mass, and a real box heaves about a third more slowly (motion.md, section 10).
#pragma once

#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_surface.hpp"

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace step07 {

constexpr double kMaxSubstep = 1.0 / 120;  // seconds: a frame of any length is cut into steps this short or shorter

enum class ShapeKind { Box, Sphere, Hull };
struct Shape {
    ShapeKind kind = ShapeKind::Box;
    glm::dvec3 size{1.0};  // a box's or a hull's length (x), depth (y, up) and beam (z); a sphere's diameter in x
};
// A boat's hull in unit coordinates (x from stern -0.5 to bow +0.5, y from keel -0.5 to deck
// +0.5): its half-beam there as a share of the beam. A fine bow and a fuller stern, both closing
// to a knife edge at their ends (half-beam 0), over flared sections: 0.3 of the half-beam at the
// keel, a flat bottom, widening to all of it at the deck. hull_cells fills it and body_mesh.cpp draws it.
double hull_half_beam(double x, double y);
double shape_volume(const Shape& shape);
// The diagonal of the inertia tensor per kilogram, in the body's frame.
glm::dvec3 inertia_per_mass(const Shape& shape);

std::vector<HullCell> hull_cells(const Shape& shape, int cells_per_side);

struct BodySettings {
    Shape shape;
    double density = 500;       // kg/m^3: below the water's it floats
    double linear_drag = 0.5;   // 1/s: the drag's rate per kilogram of water displaced
    double angular_drag = 0.5;  // 1/s, scaled by the submerged share
    int cells_per_side = 8;     // the hull's cells (a sphere's forces use its exact cap instead)
    // The centre of mass moved from the volume's centroid (body frame, metres), as ballast moves
    // it: a light hull of uniform density carries its mass high, and a beam sea rolls it over
    // to a list (the tests show it); an engine and a keel put it low.
    glm::dvec3 ballast{0.0};
};

// The water under one cell during a frame (queried once a frame): its height at the frame's
// start and end, the surface's gradient, and the water's velocity. Substeps read the tangent plane.
struct WaterPatch {
    glm::dvec2 at{0.0};
    double height_before = 0, height_now = 0;
    glm::dvec2 gradient{0.0};   // dh/dx, dh/dz of the displaced surface
    glm::dvec3 velocity{0.0};
    double height(glm::dvec2 p, double share) const;  // share: 0 at the frame's start, 1 at its end
};

class FloatingBody {
public:
    FloatingBody(const BodySettings& settings, glm::dvec3 position, glm::dquat orientation = glm::dquat(1, 0, 0, 0));

    // Advances dt seconds in equal substeps no longer than kMaxSubstep, the sea moving from
    // `before` to `now` over the frame. The water's velocity is their difference over
    // `sea_interval` seconds, the time between the two seas (dt when they are this frame's and
    // the last; the read-back's may be older); without it, dt.
    void step(const Surface& before, const Surface& now, double dt, double sea_interval = 0);
    // An impulse (N s) at a world point (the mouse's push).
    void push(glm::dvec3 impulse, glm::dvec3 at);
    // Steering: a force (N) at a point of the body's frame, for the next step only.
    void add_force(glm::dvec3 force_world, glm::dvec3 at_body);
    // Whether the water holds the body up by Archimedes on the sea's surface (the default), or
    // another model of the water pushes it, found after each step and given with add_water_push
    // (a water that moves with the hull, which Archimedes on a given surface cannot see). The drag
    // stays either way.
    void set_archimedes(bool on) { archimedes_ = on; }
    bool archimedes() const { return archimedes_; }
    // A force (N) and torque (N m) held over the last step of dt seconds, added after it: the
    // velocities change by F dt / m and I^-1 tau dt, and the position and orientation move as
    // the step's substeps would have moved them (travel_per_acceleration).
    void add_water_push(glm::dvec3 force, glm::dvec3 torque, double dt);
    // Water that moves with the body when it heaves (kg, the added mass motion.md section 10
    // estimates): its vertical motion answers to the vertical force over its mass plus this, and
    // the heave slows by sqrt(1 + added / mass). None by default: the program's bodies heave as
    // the model's closed form says.
    void set_heave_added_mass(double kg) { heave_added_mass_ = kg; }
    double heave_added_mass() const { return heave_added_mass_; }
    // How far a step of dt seconds moves a body per unit of a constant acceleration held over it:
    // semi-implicit Euler's n substeps of h = dt / n move it h^2 (1 + 2 + ... + n) = dt^2 (n + 1) / (2 n).
    static double travel_per_acceleration(double dt);
    // The inverse of the inertia tensor in world axes, R I^-1 R^T (1 / (kg m^2)).
    glm::dmat3 inverse_inertia() const { return world_inertia(true); }

    const BodySettings& settings() const { return settings_; }
    glm::dvec3 position() const { return position_; }
    glm::dquat orientation() const { return orientation_; }
    glm::dvec3 velocity() const { return velocity_; }
    glm::dvec3 angular_velocity() const { return angular_velocity_; }
    double mass() const { return mass_; }
    double volume() const { return volume_; }
    // Where the shape's box is centred, in the body's frame (the body turns about its centre of
    // mass, which for a hull is below and behind the box's centre): the mesh is drawn from there.
    glm::dvec3 shape_centre() const { return -centroid_; }
    double submerged_volume() const { return submerged_volume_; }  // after the last substep
    const std::vector<HullCell>& cells() const { return cells_; }
    // On still water at y = 0, the energy (J) the forces above can only take away: kinetic,
    // gravity's potential, and buoyancy's (each cell's force rho_w g V wet(y) is minus the
    // derivative of rho_w g V times the integral of wet from y up). Drag only lowers it.
    double energy_in_still_water() const;
    glm::dvec3 to_world(glm::dvec3 body_point) const { return position_ + orientation_ * body_point; }

private:
    void substep(double h, double share);
    // Buoyancy and drag this substep (the sea `share` of the way through the frame), with their
    // torque about the centre of mass; sets submerged_volume_.
    Wrench water_forces(const glm::dmat3& rotation, double share);
    // The inertia tensor in world axes, R I R^T, or its inverse, R I^-1 R^T.
    glm::dmat3 world_inertia(bool inverse = false) const;

    BodySettings settings_;
    std::vector<HullCell> cells_;
    std::vector<WaterPatch> water_;
    std::vector<double> water_lines_;  // this substep's, one a cell
    double mass_ = 0, volume_ = 0;
    glm::dvec3 centroid_{0.0};  // of the cells, from the shape's box centre (uniform density)
    glm::dvec3 inertia_{0.0};  // body frame, kg m^2
    glm::dvec3 position_{0.0}, velocity_{0.0}, angular_velocity_{0.0};
    glm::dquat orientation_{1, 0, 0, 0};
    glm::dvec3 extra_force_{0.0}, extra_torque_{0.0};
    double submerged_volume_ = 0;
    double heave_added_mass_ = 0;
    bool archimedes_ = true;
};

}  // namespace step07
