// What each of step07's own parameters rebuilds: a change to a body's size, density, drag or drop
// height drops the bodies again (BodyParams::changed); steering the boat and the height queries
// drop nothing. Every parameter is moved once, as the panel or --set would, and the counter read.
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/query_grid.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace {

// Another value in the parameter's range: its other end, or another choice.
double another_value(const ocean::Param& p) {
    return p.number() != p.max() ? p.max() : p.min();
}

TEST(BodyParams, OnlyTheBodiesOwnSettingsDropThemAgain) {
    // Declared as main.cpp declares them, in its order.
    ocean::ParamRegistry registry;
    step07::BodyParams bodies;
    step07::Steering steering;
    step07::QueryGrid queries;
    bodies.declare(registry);
    steering.declare(registry);
    queries.declare(registry);

    const std::set<std::string> drop_the_bodies = {"buoy_diameter", "buoy_density", "raft_size", "raft_density",
                                                   "boat_length",   "boat_density", "drag",      "drop_height"};
    std::set<std::string> moved;
    for (const auto& p : registry.all()) {
        const unsigned before = bodies.changes.value;
        p->set_number(another_value(*p));
        const bool dropped = bodies.changes.value != before;
        EXPECT_EQ(dropped, drop_the_bodies.count(p->name()) == 1)
            << p->name() << (dropped ? " drops the bodies again" : " does not drop the bodies");
        moved.insert(p->name());
    }
    std::vector<std::string> the_others = {"boat_throttle", "boat_rudder", "queries"};
#ifndef OCEAN_GL_PORTABLE
    the_others.push_back("query_device");  // the GPU's answers need compute shaders: GL 4.5 only
#endif
    for (const std::string& name : the_others) EXPECT_EQ(moved.count(name), 1u) << name << " was not declared";
    EXPECT_EQ(moved.size(), drop_the_bodies.size() + the_others.size());
}

}  // namespace
