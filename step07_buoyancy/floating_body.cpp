#include "step07_buoyancy/floating_body.hpp"

#include "step07_buoyancy/sea_query.hpp"

#include "common/constants.hpp"

#include <algorithm>
#include <cmath>

namespace step07 {

double hull_half_beam(double x, double y) {
    const double along = std::abs(2 * x), ends = x > 0 ? along * along * along : std::pow(along, 8);
    return 0.5 * std::sqrt(std::max(0.0, 1 - ends)) * (0.3 + 0.7 * (y + 0.5));
}

double shape_volume(const Shape& shape) {
    if (shape.kind == ShapeKind::Sphere) return ocean::kPi * std::pow(shape.size.x, 3) / 6;
    if (shape.kind == ShapeKind::Hull) {  // the half-beam integrated over x and y (midpoints, 128 x 128)
        double sum = 0;
        for (int i = 0; i < 128; ++i)
            for (int j = 0; j < 128; ++j)
                sum += 2 * hull_half_beam((i + 0.5) / 128 - 0.5, (j + 0.5) / 128 - 0.5);
        return sum / (128.0 * 128.0) * shape.size.x * shape.size.y * shape.size.z;
    }
    return shape.size.x * shape.size.y * shape.size.z;
}

glm::dvec3 inertia_per_mass(const Shape& shape) {
    if (shape.kind == ShapeKind::Sphere) return glm::dvec3(0.1 * shape.size.x * shape.size.x);  // 2/5 r^2
    const glm::dvec3 s2 = shape.size * shape.size;
    return glm::dvec3(s2.y + s2.z, s2.x + s2.z, s2.x + s2.y) / 12.0;
}

std::vector<HullCell> hull_cells(const Shape& shape, int n) {
    std::vector<HullCell> cells;
    const glm::dvec3 side = shape.kind == ShapeKind::Sphere ? glm::dvec3(shape.size.x / n) : shape.size / double(n);
    const glm::dvec3 corner = -0.5 * (shape.kind == ShapeKind::Sphere ? glm::dvec3(shape.size.x) : shape.size);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 offset = corner + (glm::dvec3(i, j, k) + 0.5) * side;
                if (shape.kind == ShapeKind::Sphere && glm::length(offset) > 0.5 * shape.size.x) continue;
                if (shape.kind == ShapeKind::Hull &&
                    std::abs(offset.z) >
                        shape.size.z * hull_half_beam(offset.x / shape.size.x, offset.y / shape.size.y))
                    continue;
                cells.push_back({offset, side, side.x * side.y * side.z});
            }
    // The cells' volumes add up to the shape's (a sphere's or a hull's cubes miss or overshoot its surface).
    double total = 0;
    for (const auto& c : cells) total += c.volume;
    for (auto& c : cells) c.volume *= shape_volume(shape) / total;
    return cells;
}

double WaterPatch::height(glm::dvec2 p, double share) const {
    return height_before + (height_now - height_before) * share + glm::dot(gradient, p - at);
}

FloatingBody::FloatingBody(const BodySettings& settings, glm::dvec3 position, glm::dquat orientation)
    : settings_(settings), cells_(hull_cells(settings.shape, settings.cells_per_side)), position_(position),
      orientation_(orientation) {
    // The centre of mass is the cells' centroid (zero for a box or a sphere): their offsets are
    // measured from it.
    double total = 0;
    for (const HullCell& c : cells_) centroid_ += c.volume * c.offset, total += c.volume;
    centroid_ = centroid_ / total + settings.ballast;
    for (HullCell& c : cells_) c.offset -= centroid_;
    volume_ = shape_volume(settings.shape);
    mass_ = settings.density * volume_;
    inertia_ = mass_ * inertia_per_mass(settings.shape);
    // No closed form for a hull, nor about a shifted centre of mass: from the cells, each a small
    // box, its own inertia about its centre plus its mass at its offset (parallel axes; exact for
    // a box's cells).
    if (settings.shape.kind == ShapeKind::Hull || settings.ballast != glm::dvec3(0.0)) {
        glm::dvec3 sum(0.0);
        for (const HullCell& c : cells_) {
            const glm::dvec3 o2 = c.offset * c.offset, s2 = c.size * c.size / 12.0;
            sum += c.volume * (glm::dvec3(o2.y + o2.z, o2.x + o2.z, o2.x + o2.y) +
                               glm::dvec3(s2.y + s2.z, s2.x + s2.z, s2.x + s2.y));
        }
        inertia_ = settings.density * sum;
    }
}

glm::dmat3 FloatingBody::world_inertia(bool inverse) const {
    const glm::dmat3 r = glm::mat3_cast(orientation_);
    const glm::dvec3 d = inverse ? 1.0 / inertia_ : inertia_;
    return r * glm::dmat3(glm::dvec3(d.x, 0, 0), glm::dvec3(0, d.y, 0), glm::dvec3(0, 0, d.z)) *
           glm::transpose(r);
}

void FloatingBody::step(const Surface& before, const Surface& now, double dt, double sea_interval) {
    if (dt <= 0) return;
    // The sea under each cell (a sphere: under its centre), once a frame: the queries are the
    // costly part (sea_query.hpp); the substeps move on the surface's tangent plane, which the
    // body hardly leaves in a frame.
    const bool sphere = settings_.shape.kind == ShapeKind::Sphere;
    water_.resize(sphere ? 1 : cells_.size());
    for (std::size_t i = 0; i < water_.size(); ++i) {
        const glm::dvec3 p = to_world(sphere ? shape_centre() : cells_[i].offset);
        WaterPatch& w = water_[i];
        w.at = {p.x, p.z};
        const SeaPoint at_now = query(now, w.at), at_before = query(before, w.at);
        w.height_now = at_now.height;
        w.height_before = at_before.height;
        w.gradient = glm::dvec2(-at_now.normal.x, -at_now.normal.z) / std::max(at_now.normal.y, 0.05);
        // The water beside the point moves on orbits that shrink with its depth under the surface
        // above it (0 above the water): a sunk body no longer feels the surface's motion.
        const double depth = std::max(0.0, at_now.height - p.y);
        w.velocity = water_velocity(before, now, sea_interval > 0 ? sea_interval : dt, at_now.rest, depth);
    }
    const int substeps = std::max(1, int(std::ceil(dt / kMaxSubstep - 1e-9)));
    const double h = dt / substeps;
    for (int s = 1; s <= substeps; ++s) substep(h, double(s) / substeps);
    extra_force_ = extra_torque_ = glm::dvec3(0.0);
}

Wrench FloatingBody::water_forces(const glm::dmat3& r, double share) {
    Wrench total;
    // The drag on a wet volume moving at `moving` against the water's own motion, at arm from the
    // centre of mass.
    const auto drag = [&](double volume, glm::dvec3 arm, glm::dvec3 water_velocity) {
        const glm::dvec3 moving = velocity_ + glm::cross(angular_velocity_, arm);
        const glm::dvec3 force = -kWaterDensity * volume * settings_.linear_drag * (moving - water_velocity);
        total.force += force;
        total.torque += glm::cross(arm, force);
    };
    if (settings_.shape.kind == ShapeKind::Sphere) {
        // The exact cap under the water line at the sphere's centre, through the centre.
        const glm::dvec3 arm = r * shape_centre(), centre = position_ + arm;
        const double radius = 0.5 * settings_.shape.size.x;
        const double water_line = water_[0].height({centre.x, centre.z}, share);
        const glm::dvec3 lift = archimedes_ ? sphere_buoyancy(radius, centre.y, water_line) : glm::dvec3(0.0);
        total.force += lift;
        total.torque += glm::cross(arm, lift);  // zero but for ballast
        submerged_volume_ = spherical_cap_volume(radius, water_line - (centre.y - radius));
        if (submerged_volume_ > 0) drag(submerged_volume_, arm, water_[0].velocity);
        return total;
    }
    // The water line over each cell's centre, on this substep's tangent planes.
    water_lines_.resize(cells_.size());
    for (std::size_t i = 0; i < cells_.size(); ++i) {
        const glm::dvec3 centre = position_ + r * cells_[i].offset;
        water_lines_[i] = water_[i].height({centre.x, centre.z}, share);
    }
    // Archimedes (hull_forces.cpp), then the drag on each wet cell against the water's own motion.
    if (archimedes_) total = buoyancy(cells_, r, position_, water_lines_);
    submerged_volume_ = 0;
    for (std::size_t i = 0; i < cells_.size(); ++i) {
        const glm::dvec3 arm = r * cells_[i].offset;
        const double wet = wet_share(water_lines_[i], position_.y + arm.y, vertical_half_extent(r, cells_[i]));
        if (wet <= 0) continue;
        submerged_volume_ += wet * cells_[i].volume;
        drag(wet * cells_[i].volume, arm, water_[i].velocity);
    }
    return total;
}

void FloatingBody::substep(double h, double share) {
    const glm::dmat3 r = glm::mat3_cast(orientation_);
    glm::dvec3 force(0.0, -mass_ * ocean::kGravity, 0.0), torque(0.0);
    force += extra_force_;
    torque += extra_torque_;
    const Wrench water = water_forces(r, share);
    force += water.force;
    torque += water.torque;
    const glm::dmat3 inverse_inertia = world_inertia(true), inertia = world_inertia();
    const double submerged_share = submerged_volume_ / volume_;
    torque -= settings_.angular_drag * submerged_share * (inertia * angular_velocity_);
    // Semi-implicit Euler: velocities first, then positions with the new velocities. Symplectic:
    // it conserves a nearby energy exactly, so an undamped oscillator's energy stays within a
    // band of about h omega / 2 of its start instead of growing, as explicit Euler's would.
    force.y *= mass_ / (mass_ + heave_added_mass_);  // the water carried in heave takes its share (none by default)
    velocity_ += h * force / mass_;
    position_ += h * velocity_;
    const glm::dvec3 gyroscopic = glm::cross(angular_velocity_, inertia * angular_velocity_);
    angular_velocity_ += h * (inverse_inertia * (torque - gyroscopic));
    orientation_ = glm::normalize(orientation_ + 0.5 * h * glm::dquat(0.0, angular_velocity_) * orientation_);
}

void FloatingBody::push(glm::dvec3 impulse, glm::dvec3 at) {
    velocity_ += impulse / mass_;
    angular_velocity_ += world_inertia(true) * glm::cross(at - position_, impulse);
}

double FloatingBody::travel_per_acceleration(double dt) {
    const int n = std::max(1, int(std::ceil(dt / kMaxSubstep - 1e-9)));  // step()'s substeps
    return dt * dt * (n + 1) / (2.0 * n);
}

void FloatingBody::add_water_push(glm::dvec3 force, glm::dvec3 torque, double dt) {
    const glm::dvec3 alpha = world_inertia(true) * torque;
    const double travel = travel_per_acceleration(dt);
    velocity_ += dt * force / mass_;
    position_ += travel * force / mass_;
    angular_velocity_ += dt * alpha;
    orientation_ = glm::normalize(orientation_ + 0.5 * glm::dquat(0.0, travel * alpha) * orientation_);
}

void FloatingBody::add_force(glm::dvec3 force_world, glm::dvec3 at_body) {
    extra_force_ += force_world;
    extra_torque_ += glm::cross(orientation_ * at_body, force_world);
}

double FloatingBody::energy_in_still_water() const {
    const glm::dmat3 r = glm::mat3_cast(orientation_);
    const glm::dmat3 inertia = world_inertia();
    double energy = 0.5 * mass_ * glm::dot(velocity_, velocity_) +
                    0.5 * glm::dot(angular_velocity_, inertia * angular_velocity_) + mass_ * ocean::kGravity * position_.y;
    if (settings_.shape.kind == ShapeKind::Sphere) {
        // The integral of the cap's volume V(s) = pi (r s^2 - s^3 / 3) over the draft s from 0 to d,
        // pi (r d^3 / 3 - d^4 / 12); once under (d = 2 r), the whole volume for each metre deeper.
        const double radius = 0.5 * settings_.shape.size.x, y = (position_ + r * shape_centre()).y;
        const double d = std::clamp(radius - y, 0.0, 2 * radius), below = std::max(0.0, -radius - y);
        const double integral = ocean::kPi * (radius * d * d * d / 3 - d * d * d * d / 12) + volume_ * below;
        return energy + kWaterDensity * ocean::kGravity * integral;
    }
    for (const HullCell& cell : cells_) {
        const double y = position_.y + (r * cell.offset).y, e = vertical_half_extent(r, cell);
        // The integral of wet(y') = clamp((e - y') / 2e, 0, 1) from y to e (the water line at 0).
        const double integral = y <= -e ? -y : (y < e ? (e - y) * (e - y) / (4 * e) : 0.0);
        energy += kWaterDensity * ocean::kGravity * cell.volume * integral;
    }
    return energy;
}

}  // namespace step07
