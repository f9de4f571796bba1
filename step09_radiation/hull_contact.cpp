#include "step09_radiation/hull_contact.hpp"

#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_query.hpp"

#include "common/constants.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace step09 {

namespace {

// Half the body's diagonal: no point of it is further from its centre.
double reach(const step07::FloatingBody& body) { return 0.5 * glm::length(body.settings().shape.size); }

// How many points bottom_points puts along a box's x side and across its z side: as many as cells
// in the side's length seen from above. A tilted side is shorter on the field, and points closer
// than a cell there would read the same cells alike, making the contact's system singular (ten
// points a side did at a tilt of 40 degrees).
struct BottomGrid {
    int along, across;
};
BottomGrid bottom_grid(const step07::FloatingBody& body, double cell) {
    const glm::dvec3 size = body.settings().shape.size;
    const auto points_along = [&](glm::dvec3 axis, double length) {
        const glm::dvec3 side = body.orientation() * axis;
        return std::max(1, int(std::lround(length * std::hypot(side.x, side.z) / cell)));
    };
    return {points_along({1, 0, 0}, size.x), points_along({0, 0, 1}, size.z)};
}

}  // namespace

bool within_field(const WaveField& field, const step07::FloatingBody& body) {
    const glm::dvec3 centre = body.to_world(body.shape_centre());
    const glm::dvec2 middle = field.cell_centre(field.n() / 2, field.n() / 2);
    const double inner = 0.5 * field.side() - field.settings().absorbing_width - field.settings().cell;
    return std::abs(centre.x - middle.x) + reach(body) < inner && std::abs(centre.z - middle.y) + reach(body) < inner;
}

bool level_enough(const step07::FloatingBody& body) {
    const glm::dvec3 up = body.orientation() * glm::dvec3(0, 1, 0);
    return up.y > std::cos(kMaxContactTilt * ocean::kPi / 180);
}

bool can_touch(const WaveField& field, const step07::FloatingBody& body) {
    if (body.settings().shape.kind != step07::ShapeKind::Box || !within_field(field, body) || !level_enough(body)) return false;
    const BottomGrid grid = bottom_grid(body, field.settings().cell);
    return std::size_t(grid.along) * std::size_t(grid.across) <= kMaxContactPoints;
}

std::vector<glm::dvec3> bottom_points(const step07::FloatingBody& body, double cell) {
    const glm::dvec3 size = body.settings().shape.size;
    const auto [along, across] = bottom_grid(body, cell);
    std::vector<glm::dvec3> points;
    for (int b = 0; b < across; ++b)
        for (int a = 0; a < along; ++a)
            points.push_back(body.shape_centre() + glm::dvec3(size.x * ((a + 0.5) / along - 0.5), -0.5 * size.y,
                                                                size.z * ((b + 0.5) / across - 0.5)));
    return points;
}

HullInContact hull_contact(const WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea, double h) {
    HullInContact hull;
    Contact& c = hull.contact;
    c.push_only = true;
    c.taps = 4;
    for (const glm::dvec3& point : bottom_points(body, field.settings().cell)) {
        const glm::dvec3 at = body.to_world(point);
        WaveField::Taps taps;
        if (!field.bilinear_taps({at.x, at.z}, taps)) continue;
        const double field_height = field.height_at({at.x, at.z}), sea_height = step07::query(sea, {at.x, at.z}).height;
        // Points a little over the water too: whether the water reaches them by the step's end is
        // the contact's to find (push_only).
        if (at.y >= sea_height + field_height + 0.5 * field.settings().cell) continue;
        c.cells.insert(c.cells.end(), taps.cells, taps.cells + 4);
        c.weights.insert(c.weights.end(), taps.weights, taps.weights + 4);
        c.target.push_back(at.y - sea_height);
        hull.arms.push_back(at - body.position());
    }
    // Per unit density, as the pushes are: the mass a volume, the inertia a volume times m^2.
    const std::size_t m = hull.arms.size();
    const double density = step07::kWaterDensity, travel = step07::FloatingBody::travel_per_acceleration(h);
    const glm::dmat3 inverse_inertia = density * body.inverse_inertia();
    c.compliance.resize(m * m);
    for (std::size_t a = 0; a < m; ++a) {
        const glm::dvec3 turn_a = glm::cross(hull.arms[a], glm::dvec3(0, 1, 0));
        for (std::size_t b = 0; b < m; ++b) {
            const glm::dvec3 turn_b = glm::cross(hull.arms[b], glm::dvec3(0, 1, 0));
            c.compliance[a * m + b] = travel * (density / body.mass() + glm::dot(turn_a, inverse_inertia * turn_b));
        }
    }
    return hull;
}

void push_hull(step07::FloatingBody& body, const HullInContact& hull, const std::vector<double>& pushes, double h) {
    glm::dvec3 force(0.0), torque(0.0);
    for (std::size_t c = 0; c < hull.arms.size(); ++c) {
        const glm::dvec3 push(0, step07::kWaterDensity * pushes[c], 0);
        force += push;
        torque += glm::cross(hull.arms[c], push);
    }
    body.add_water_push(force, torque, h);
}

namespace {

// The dent a steady push holds under a body floating still, read at each of its bottom's points
// where that point is (less the sea's height): under a steady push the field rests at -p / g, cell
// by cell, with p = sum of w Q / dA over the points reaching the cell, so the pushes solve
//     sum_j (sum over shared cells of w w') Q_j = -g dA target_i
// (symmetric, positive definite: the points' weights are independent rows). The dent's depth on
// each cell it touches (zero elsewhere), and which cells those are.
struct Dent {
    std::vector<double> depth;
    std::vector<char> under;
};
Dent static_dent(const WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea) {
    const HullInContact hull = hull_contact(field, body, sea, 1.0 / 60);
    const Contact& c = hull.contact;
    const std::size_t m = c.target.size();
    Dent dent{std::vector<double>(field.heights().size(), 0.0), std::vector<char>(field.heights().size(), 0)};
    if (m == 0) return dent;
    const double area = field.settings().cell * field.settings().cell;
    std::vector<double> a(m * m, 0.0), q(m);
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < m; ++j)
            for (int t = 0; t < 4; ++t)
                for (int u = 0; u < 4; ++u)
                    if (c.cells[4 * i + t] == c.cells[4 * j + u]) a[i * m + j] += c.weights[4 * i + t] * c.weights[4 * j + u];
        q[i] = -ocean::kGravity * area * c.target[i];
    }
    solve_symmetric(a, q, m);
    for (std::size_t i = 0; i < m; ++i)
        for (int t = 0; t < 4; ++t) {
            dent.depth[c.cells[4 * i + t]] -= c.weights[4 * i + t] * q[i] / (area * ocean::kGravity);
            dent.under[c.cells[4 * i + t]] = 1;
        }
    return dent;
}

}  // namespace

void settle_under(WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea) {
    const Dent dent = static_dent(field, body, sea);
    for (std::size_t k = 0; k < dent.depth.size(); ++k)
        if (dent.under[k]) field.heights()[k] = dent.depth[k];
}

void lift_out(WaveField& field, const step07::FloatingBody& body, const step07::Surface& sea) {
    const Dent dent = static_dent(field, body, sea);
    for (std::size_t k = 0; k < dent.depth.size(); ++k) field.heights()[k] -= dent.depth[k];
}

void step_with_bodies(WaveField& field, ContactStep& contact, const std::vector<step07::FloatingBody*>& bodies,
                      const step07::Surface& from, const step07::Surface& to, double h, double sea_interval,
                      const Forcing& forcing) {
    std::vector<HullInContact> hulls;
    Contact all;
    all.push_only = true;
    all.taps = 4;
    for (step07::FloatingBody* body : bodies) {
        body->set_archimedes(false);
        body->step(from, to, h, sea_interval);
        hulls.push_back(hull_contact(field, *body, to, h));
        all.cells.insert(all.cells.end(), hulls.back().contact.cells.begin(), hulls.back().contact.cells.end());
        all.weights.insert(all.weights.end(), hulls.back().contact.weights.begin(), hulls.back().contact.weights.end());
        all.target.insert(all.target.end(), hulls.back().contact.target.begin(), hulls.back().contact.target.end());
    }
    const std::size_t m = all.target.size();
    all.compliance.assign(m * m, 0.0);
    std::size_t first = 0;
    for (const HullInContact& hull : hulls) {
        const std::size_t k = hull.arms.size();
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = 0; b < k; ++b) all.compliance[(first + a) * m + first + b] = hull.contact.compliance[a * k + b];
        first += k;
    }
    const std::vector<double> pushes = contact.step(field, h, all, forcing);
    first = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const std::size_t k = hulls[b].arms.size();
        push_hull(*bodies[b], hulls[b], std::vector<double>(pushes.begin() + long(first), pushes.begin() + long(first + k)), h);
        first += k;
    }
}

step07::SurfaceAt SeaBetween::at(glm::dvec2 rest) const {
    const step07::SurfaceAt a = from_.at(rest), b = to_.at(rest);
    const auto mix = [this](glm::dvec3 x, glm::dvec3 y) { return x + share_ * (y - x); };
    return {mix(a.displacement, b.displacement), mix(a.d_dx, b.d_dx), mix(a.d_dz, b.d_dz)};
}

glm::dvec3 SeaBetween::displacement_below(glm::dvec2 rest, double depth) const {
    const glm::dvec3 a = from_.displacement_below(rest, depth), b = to_.displacement_below(rest, depth);
    return a + share_ * (b - a);
}

}  // namespace step09
