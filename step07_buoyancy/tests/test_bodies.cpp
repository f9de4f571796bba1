// What a learner does to the bodies in the window (bodies.hpp), on a flat sea at the defaults: the
// numbers step07's README quotes. The arrows move the boat visibly within a second, a right click
// carries a body about its own size in the first second, and the bodies are dropped where the
// panel does not hide them.
#include "step07_buoyancy/bodies.hpp"

#include "step07_buoyancy/sea_surface.hpp"

#include "common/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace {

using step07::FloatingBody;

const step07::FlatSea kCalm;
constexpr double kDt = 1.0 / 60;
constexpr double kDegrees = 180 / 3.14159265358979323846;

// The three bodies at the defaults, dropped before a camera at the origin looking along +x, then
// left 15 s to settle on the flat sea.
std::vector<FloatingBody> settled_bodies() {
    std::vector<FloatingBody> bodies = step07::drop_bodies(step07::BodyParams{}, {0, 3, 0}, {1, 0});
    for (int i = 0; i < 15 * 60; ++i)
        for (auto& body : bodies) body.step(kCalm, kCalm, kDt);
    return bodies;
}

glm::dvec2 flat(glm::dvec3 v) { return {v.x, v.z}; }
double heading(const FloatingBody& body) {
    const glm::dvec3 along = body.orientation() * glm::dvec3(1, 0, 0);
    return std::atan2(along.z, along.x);
}

// Runs `seconds` with the throttle and rudder held (1: full, as an arrow held).
void steer_for(FloatingBody& boat, double seconds, double throttle, double rudder) {
    for (int i = 0; i < int(std::lround(seconds / kDt)); ++i) {
        step07::steer(boat, throttle, rudder);
        boat.step(kCalm, kCalm, kDt);
    }
}

// A body's footprint seen from above: its shape's length (x) and width (z) turned by its
// heading (a sphere: the square around its circle). Four corners.
std::array<glm::dvec2, 4> footprint(const FloatingBody& body) {
    const glm::dvec3 size = body.settings().shape.size;
    const glm::dvec2 along = glm::normalize(flat(body.orientation() * glm::dvec3(1, 0, 0)));
    const glm::dvec2 across(-along.y, along.x), centre = flat(body.position());
    const glm::dvec2 a = 0.5 * size.x * along, b = 0.5 * size.z * across;
    return {centre + a + b, centre + a - b, centre - a - b, centre - a + b};
}

// Two convex footprints overlap unless some edge's normal separates them (separating axes).
bool overlap(const std::array<glm::dvec2, 4>& p, const std::array<glm::dvec2, 4>& q) {
    for (const auto* shape : {&p, &q})
        for (int e = 0; e < 4; ++e) {
            const glm::dvec2 edge = (*shape)[(e + 1) % 4] - (*shape)[e], axis(-edge.y, edge.x);
            double p_min = 1e300, p_max = -1e300, q_min = 1e300, q_max = -1e300;
            for (const glm::dvec2& c : p) p_min = std::min(p_min, glm::dot(c, axis)), p_max = std::max(p_max, glm::dot(c, axis));
            for (const glm::dvec2& c : q) q_min = std::min(q_min, glm::dot(c, axis)), q_max = std::max(q_max, glm::dot(c, axis));
            if (p_max < q_min || q_max < p_min) return false;
        }
    return true;
}

TEST(Bodies, FootprintsOverlapOnlyWhenTheyDo) {
    FloatingBody a(step07::body_settings(step07::BodyParams{})[step07::kRaft], {0, 0, 0});
    FloatingBody b(step07::body_settings(step07::BodyParams{})[step07::kRaft], {4.9, 0, 0});
    FloatingBody c(step07::body_settings(step07::BodyParams{})[step07::kRaft], {5.1, 0, 0});
    // The 5 m raft turned 45 degrees reaches 2.5 sqrt 2 = 3.54 m from its centre: 6.04 m in all.
    const glm::dquat turned = glm::angleAxis(0.25 * 3.14159265358979323846, glm::dvec3(0, 1, 0));
    FloatingBody d(a.settings(), {6.1, 0, 0}, turned), e(a.settings(), {5.9, 0, 0}, turned);
    EXPECT_TRUE(overlap(footprint(a), footprint(b)));
    EXPECT_FALSE(overlap(footprint(a), footprint(c)));
    EXPECT_FALSE(overlap(footprint(a), footprint(d)));
    EXPECT_TRUE(overlap(footprint(a), footprint(e)));
}

TEST(Bodies, DroppedInFrontAndRightOfTheViewApartFromEachOther) {
    // The camera at the origin looking along +x: ahead is +x, the view's right is +z.
    const std::vector<FloatingBody> bodies = step07::drop_bodies(step07::BodyParams{}, {0, 3, 0}, {1, 0});
    ASSERT_EQ(bodies.size(), 3u);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const glm::dvec3 p = bodies[i].position();
        EXPECT_GT(p.x, 10.0) << step07::kBodyNames[i] << " in front of the camera";
        EXPECT_GE(p.z, 0.0) << step07::kBodyNames[i] << " in the right half of the view (the panel is at the left)";
        EXPECT_NEAR(p.y, step07::BodyParams{}.drop_height, 1e-12);
        for (std::size_t j = 0; j < i; ++j) {
            EXPECT_FALSE(overlap(footprint(bodies[i]), footprint(bodies[j])))
                << step07::kBodyNames[i] << " and " << step07::kBodyNames[j] << " are dropped apart";
        }
    }
}

TEST(Bodies, TheUpArrowMovesTheBoatVisiblyWithinASecond) {
    // README: 1.7 m in the first second, 7 m/s after five (k g (1 - (1 - e^-c) / c) / c at k = 0.4).
    FloatingBody boat = settled_bodies()[step07::kBoat];
    const glm::dvec3 start = boat.position();
    steer_for(boat, 1, 1, 0);
    const double first_second = glm::length(flat(boat.position() - start));
    steer_for(boat, 4, 1, 0);
    const double speed = glm::length(flat(boat.velocity()));
    std::cout << "up arrow: " << first_second << " m in the first second, " << speed << " m/s after five\n";
    EXPECT_NEAR(first_second, 1.7, 0.35);
    EXPECT_NEAR(speed, 7.0, 1.0);
    const glm::dvec2 moved = glm::normalize(flat(boat.position() - start));
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    EXPECT_GT(glm::dot(moved, glm::normalize(flat(along))), 0.95) << "forward, along its length";
}

TEST(Bodies, TheSideArrowTurnsTheBoatVisiblyWithinASecond) {
    // README: 16 degrees in the first second; the right arrow turns it to its right: a boat heading
    // along +x has its starboard at +z (x cross y), so its heading's angle in x-z grows.
    FloatingBody boat = settled_bodies()[step07::kBoat];
    const double before = heading(boat);
    steer_for(boat, 1, 0, 1);
    const double turned = std::remainder(heading(boat) - before, 2 * 3.14159265358979323846) * kDegrees;
    std::cout << "right arrow: " << turned << " degrees in the first second\n";
    EXPECT_GT(turned, 0.0) << "the right arrow swings the bow to starboard";
    EXPECT_NEAR(std::abs(turned), 16.0, 4.0);
}

TEST(Bodies, APushCarriesEachBodyAboutItsOwnSizeInTheFirstSecond) {
    // README: the buoy 3.8 m/s and 3 m, the raft 6.4 m/s and 5 m, the boat 7.6 m/s and 6 m.
    const double expected_speed[3] = {3.8, 6.4, 7.6}, expected_distance[3] = {3, 5, 6};
    std::vector<FloatingBody> bodies = settled_bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        FloatingBody& body = bodies[i];
        const double speed = step07::push_speed(body);
        const glm::dvec3 start = body.position(), away(0, 0, 1);
        body.push(speed * body.mass() * away, body.position());  // through the centre: no spin
        for (int s = 0; s < 60; ++s) body.step(kCalm, kCalm, kDt);
        const double moved = glm::dot(body.position() - start, away);
        std::cout << step07::kBodyNames[i] << ": pushed at " << speed << " m/s, " << moved << " m in the first second\n";
        EXPECT_NEAR(speed, expected_speed[i], 0.05) << step07::kBodyNames[i];
        EXPECT_NEAR(moved, expected_distance[i], 0.2 * expected_distance[i]) << step07::kBodyNames[i];
    }
}

}  // namespace

namespace {

TEST(Bodies, ThePanelAndAnArrowTogetherGiveNoMoreThanFull) {
    // The panel's throttle at 1 plus the up arrow held is still full ahead (steer clamps the sum).
    const FloatingBody start = settled_bodies()[step07::kBoat];
    FloatingBody full = start, doubled = start, half = start;
    steer_for(full, 1, 1, 0);
    steer_for(doubled, 1, 2, 0);
    steer_for(half, 1, 0.5, 0);
    const double d_full = glm::length(flat(full.position() - start.position()));
    EXPECT_NEAR(glm::length(flat(doubled.position() - start.position())), d_full, 1e-12);
    EXPECT_NEAR(glm::length(flat(half.position() - start.position())), 0.5 * d_full, 0.1 * d_full)
        << "half the throttle, about half the distance (the drag is linear)";
}

}  // namespace

namespace {

TEST(Bodies, AStalledFrameAdvancesTheBodiesNoFurtherThanHalfASecond) {
    // A 5 s frame with the up arrow read at its end (auto's backend trial under a slow build): the
    // boat moves as in a 0.5 s frame, not ten times as far (CI's steer_push saw 23 m and half a turn).
    std::vector<FloatingBody> stalled = settled_bodies(), capped = stalled, normal = stalled;
    const glm::dvec3 start = stalled[step07::kBoat].position();
    const auto frame = [](std::vector<FloatingBody>& bodies, double dt) {
        step07::steer(bodies[step07::kBoat], 1, 0);
        step07::advance_bodies(bodies, kCalm, kCalm, dt, dt);
    };
    frame(stalled, 5.0);
    frame(capped, step07::kMaxBodyFrame);
    for (int i = 0; i < 3; ++i) frame(normal, 0.1);  // frames shorter than the cap run at real speed
    const double d_stalled = glm::length(flat(stalled[step07::kBoat].position() - start));
    const double d_capped = glm::length(flat(capped[step07::kBoat].position() - start));
    const double d_normal = glm::length(flat(normal[step07::kBoat].position() - start));
    EXPECT_NEAR(d_stalled, d_capped, 1e-12);
    EXPECT_GT(d_capped, 0.0);
    // 0.3 s at full thrust from rest: about 0.4 g t^2 / 2 = 0.18 m (the drag barely acts yet).
    EXPECT_NEAR(d_normal, 0.5 * step07::kFullThrust * ocean::kGravity * 0.09, 0.03);
}

}  // namespace
