// step07's raft in contact with the wave field (hull_contact.hpp), as step08's program floats it.
#include "step09_radiation/hull_contact.hpp"
#include "step09_radiation/radiation_experiments.hpp"

#include "step07_buoyancy/bodies.hpp"

#include "common/constants.hpp"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

namespace {

step07::BodySettings raft_settings() {
    step07::BodyParams params;
    return step07::body_settings(params)[step07::kRaft];
}

// The program's grid: the defaults, 128 cells of half a metre, an 8 m absorbing layer.
step09::WaveFieldSettings field_settings() { return {}; }

// The raft's rest on still water: its draft d = density / 1025 of its 0.4 m.
double rest_height(const step07::BodySettings& raft) {
    return raft.shape.size.y * (0.5 - raft.density / step07::kWaterDensity);
}

// The raft's heave (its centre's height above its rest) over `seconds`, released `lift` metres
// above its rest on calm water: in contact with the field, or on step07's Archimedes alone.
step09::HeaveRecord release_raft(bool with_waves, double lift = 0.05, double seconds = 6, double linear_drag = 0.5) {
    step07::BodySettings settings = raft_settings();
    settings.linear_drag = linear_drag;
    settings.angular_drag = 0;
    const double rest = rest_height(settings);
    step07::FloatingBody raft(settings, {0.25, rest + lift, 0.25});  // its bottom's points on cell centres
    step09::WaveField field(field_settings());
    step09::ContactStep contact;
    const step07::FlatSea calm;
    const double dt = 1.0 / 60;
    // Held there until the water has settled under it (as release_hemisphere holds the hemisphere).
    if (with_waves) step09::settle_under(field, raft, calm);
    step09::HeaveRecord record;
    record.rest = rest;
    for (int s = 0; s <= int(std::lround(seconds / dt)); ++s) {
        record.time.push_back(s * dt);
        record.height.push_back(raft.position().y - rest);
        if (with_waves)
            step09::step_with_bodies(field, contact, {&raft}, calm, calm, dt, dt);
        else
            raft.step(calm, calm, dt);
    }
    return record;
}

TEST(Step09HullContact, TheRaftsBottomIsAPointACell) {
    const step07::FloatingBody raft(raft_settings(), {1, 2, 3});
    const std::vector<glm::dvec3> points = step09::bottom_points(raft, 0.5);
    ASSERT_EQ(points.size(), 100u);  // 5 m by 5 m in half-metre cells
    glm::dvec3 middle(0.0);
    for (const glm::dvec3& p : points) {
        EXPECT_NEAR(p.y, -0.2, 1e-12);
        EXPECT_LT(std::max(std::abs(p.x), std::abs(p.z)), 2.5);
        middle += p / double(points.size());
    }
    EXPECT_LT(glm::length(middle - glm::dvec3(0, -0.2, 0)), 1e-12) << "centred under the centre of mass";
}

// Seen from above a tilted side is shorter: fewer points along it, still about one a cell.
TEST(Step09HullContact, ATiltedBottomKeepsAPointACellAsTheFieldSeesIt) {
    const step07::FloatingBody tilted(raft_settings(), {1, 2, 3}, glm::angleAxis(glm::radians(40.0), glm::dvec3(0, 0, 1)));
    // 5 m by 5 m, the x side seen 5 cos 40 = 3.83 m long: 8 points along it, 10 across.
    EXPECT_EQ(step09::bottom_points(tilted, 0.5).size(), 80u);
    EXPECT_TRUE(step09::level_enough(tilted));
    const step07::FloatingBody tossed(raft_settings(), {1, 2, 3}, glm::angleAxis(glm::radians(50.0), glm::dvec3(0, 0, 1)));
    EXPECT_FALSE(step09::level_enough(tossed)) << "tilted past 45 degrees it floats on Archimedes";
}

// The contact's system stays solvable, and the field sane, at any yaw and any tilt the contact
// takes: the raft put at random places, heights and orientations (tilts up to kMaxContactTilt),
// the water settled under it, then four steps. With ten points a side whatever the tilt, the
// system was singular from a tilt of 40 degrees (the program stopped on it in a browser).
TEST(Step09HullContact, TheContactHoldsAtAnyYawAndTiltItTakes) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const step07::FlatSea calm;
    double highest = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dquat yaw = glm::angleAxis(ocean::kTwoPi * unit(random), glm::dvec3(0, 1, 0));
        const double axis = ocean::kTwoPi * unit(random), tilt = glm::radians(step09::kMaxContactTilt) * std::sqrt(unit(random));
        const glm::dquat tilted = glm::angleAxis(tilt, glm::dvec3(std::cos(axis), 0, std::sin(axis))) * yaw;
        step07::FloatingBody raft(raft_settings(), {unit(random), -0.4 + 0.6 * unit(random), unit(random)}, tilted);
        ASSERT_TRUE(step09::level_enough(raft));
        step09::WaveField field(field_settings());
        step09::ContactStep contact;
        ASSERT_NO_THROW(step09::settle_under(field, raft, calm)) << "trial " << trial;
        for (int s = 0; s < 4; ++s) ASSERT_NO_THROW(step09::step_with_bodies(field, contact, {&raft}, calm, calm, 1.0 / 60, 1.0 / 60)) << "trial " << trial;
        for (double h : field.heights()) {
            ASSERT_TRUE(std::isfinite(h));
            highest = std::max(highest, std::abs(h));
        }
    }
    // The deepest a 5 m raft's corner goes here: its centre 0.4 m below the water, half its
    // diagonal at 45 degrees (3.54 sin 45 = 2.5 m) and its half-thickness, about 3 m; the water is
    // held to twice that (singular, the systems put it hundreds of metres off).
    std::cout << "largest height in the field: " << highest << " m" << std::endl;
    EXPECT_LT(highest, 6.0);
}

// The contact takes the default raft at the middle of the program's field, but not a raft tilted
// past 45 degrees, one out in the absorbing layer, nor one with more points than its system
// should solve every step (a 12 m raft on 25 cm cells: 48 x 48 points).
TEST(Step09HullContact, TheContactTakesTheBodiesItCanHold) {
    const step09::WaveField field(field_settings());
    EXPECT_TRUE(step09::can_touch(field, step07::FloatingBody(raft_settings(), {0.25, 0, 0.25})));
    EXPECT_FALSE(step09::can_touch(field, step07::FloatingBody(raft_settings(), {0.25, 0, 0.25},
                                                               glm::angleAxis(glm::radians(50.0), glm::dvec3(1, 0, 0)))));
    EXPECT_FALSE(step09::can_touch(field, step07::FloatingBody(raft_settings(), {29, 0, 0.25})));
    step09::WaveFieldSettings fine;
    fine.n = 256;
    fine.cell = 0.25;
    step07::BodySettings big = raft_settings();
    big.shape.size = {12, 0.4, 12};
    const step07::FloatingBody wide(big, {0.1, 0, 0.1});
    EXPECT_EQ(step09::bottom_points(wide, fine.cell).size(), 48u * 48u);
    EXPECT_FALSE(step09::can_touch(step09::WaveField(fine), wide));
    big.shape.size = {5, 0.4, 5};
    EXPECT_TRUE(step09::can_touch(step09::WaveField(fine), step07::FloatingBody(big, {0.1, 0, 0.1}))) << "400 points";
}

TEST(Step09HullContact, ABodyLeavingTakesItsDentAway) {
    // Settled under a raft (turned, off the cells' lattice), the field holds about the water it
    // displaces: its bottom's points read it where the bottom is, but the cells they read reach
    // half a cell past the bottom's edge, which the dent fills too (12 % more here; none when the
    // points sit on cell centres). Lifted out, the field is flat again.
    const step07::BodySettings settings = raft_settings();
    const step07::FloatingBody raft(settings, {0.1, rest_height(settings), 0.3}, glm::angleAxis(0.4, glm::dvec3(0, 1, 0)));
    step09::WaveField field(field_settings());
    step09::ContactStep contact;
    const step07::FlatSea calm;
    step09::settle_under(field, raft, calm);
    double displaced = 0;
    for (double h : field.heights()) displaced -= h * 0.25;
    const double draft = settings.shape.size.y * settings.density / step07::kWaterDensity;
    std::cout << "the dent holds " << displaced << " m^3; the raft displaces " << 25 * draft << " m^3" << std::endl;
    EXPECT_NEAR(displaced, 25 * draft, 0.15 * 25 * draft);
    step09::lift_out(field, raft, calm);
    double largest = 0;
    for (double h : field.heights()) largest = std::max(largest, std::abs(h));
    EXPECT_LT(largest, 1e-12);
}

TEST(Step09HullContact, AtRestTheFieldHoldsTheRaftWhereArchimedesDoes) {
    // Put at its rest on calm water, the raft stays there: the contact's pressure is g times its
    // draft, its weight over its bottom's area.
    const step09::HeaveRecord record = release_raft(true, 0.0, 2);
    double largest = 0;
    for (double h : record.height) largest = std::max(largest, std::abs(h));
    std::cout << "raft at rest: moved at most " << largest << " m" << std::endl;
    EXPECT_LT(largest, 1e-3);
}

TEST(Step09HullContact, AHeavingRaftLosesItsEnergyToTheWavesItMakes) {
    // Without drag, so that the waves alone take the energy: on Archimedes the raft rings for ever;
    // in contact with the field it comes to rest within a few periods, its period lengthened by
    // the water it drags along.
    const step09::Decay alone = step09::measure_decay(release_raft(false, 0.05, 6, 0.0), 4);
    const step09::Decay waves = step09::measure_decay(release_raft(true, 0.05, 6, 0.0), 2);  // the third is lost in the noise
    std::cout << "raft on Archimedes: period " << alone.period << " s, damping ratio " << alone.damping_ratio
              << "; with its waves: period " << waves.period << " s, damping ratio " << waves.damping_ratio << std::endl;
    ASSERT_EQ(alone.crests, 4);
    ASSERT_EQ(waves.crests, 2);
    EXPECT_LT(std::abs(alone.damping_ratio), 0.01);
    EXPECT_GT(waves.damping_ratio, 0.1);
    EXPECT_GT(waves.period, alone.period);
}

TEST(Step09HullContact, TheWaterPushesButNeverPulls) {
    // A raft 10 cm over calm water: its points are near enough to be asked (half a cell), but the
    // water would have to be pulled up to them. It falls freely, and the water stays flat.
    step07::BodySettings settings = raft_settings();
    settings.linear_drag = 0;
    step07::FloatingBody raft(settings, {0.25, 0.2 + 0.1, 0.25});
    step09::WaveField field(field_settings());
    step09::ContactStep contact;
    const step07::FlatSea calm;
    const double dt = 1.0 / 60;
    ASSERT_FALSE(step09::hull_contact(field, raft, calm, dt).arms.empty()) << "the points are asked";
    step09::step_with_bodies(field, contact, {&raft}, calm, calm, dt, dt);
    EXPECT_NEAR(raft.velocity().y, -ocean::kGravity * dt, 1e-12);
    double largest = 0;
    for (double h : field.heights()) largest = std::max(largest, std::abs(h));
    EXPECT_EQ(largest, 0.0);
}

TEST(Step09HullContact, TheRaftsEnergyGoesIntoTheWaves) {
    // No drag and no absorbing layer: what the raft loses (its fall from 5 cm over its rest, in
    // kinetic and potential energy) the field gains, in its waves and its dent. Their sum stays
    // constant to within 0.1 % of what passes between them.
    step07::BodySettings settings = raft_settings();
    settings.linear_drag = 0;
    settings.angular_drag = 0;
    step07::FloatingBody raft(settings, {0.25, rest_height(settings) + 0.05, 0.25});
    step09::WaveFieldSettings grid = field_settings();
    grid.absorbing_width = 0;
    step09::WaveField field(grid);
    step09::ContactStep contact;
    const step07::FlatSea calm;
    step09::settle_under(field, raft, calm);
    const auto total = [&] {
        const glm::dvec3 v = raft.velocity();
        return 0.5 * raft.mass() * glm::dot(v, v) + raft.mass() * ocean::kGravity * raft.position().y +
               step07::kWaterDensity * field.energy();
    };
    const double start = total(), body_start = raft.mass() * ocean::kGravity * raft.position().y;
    double drift = 0, passed = 0;
    for (int s = 0; s < 240; ++s) {
        step09::step_with_bodies(field, contact, {&raft}, calm, calm, 1.0 / 60, 1.0 / 60);
        drift = std::max(drift, std::abs(total() - start));
        passed = std::max(passed, body_start - raft.mass() * ocean::kGravity * raft.position().y);
    }
    std::cout << "energy: " << passed << " J passed from the raft to the field; the sum drifted " << drift << " J"
              << std::endl;
    EXPECT_GT(passed, 1000.0);
    EXPECT_LT(drift, 1e-3 * passed);
}

}  // namespace
