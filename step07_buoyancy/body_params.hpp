// The bodies' settings as the panel, --set and presets see them. A change to any of BodyParams
// drops the bodies again (a new size or density is a new body); the boat's Steering is read every
// frame and drops nothing, so it is declared in a group of its own, with no change counter.
#pragma once

#include "common/params.hpp"

namespace step07 {

struct BodyParams {
    float buoy_diameter = 1.2f, buoy_density = 350, raft_size = 5, raft_density = 450;
    float boat_length = 9, boat_density = 300, drag = 0.5f, drop_height = 1.5f;
    ocean::Generation changes;  // bumped by each parameter above: the bodies are dropped again

    void declare(ocean::ParamRegistry& p) {
        const auto group = p.group("bodies", &changes);
        p.add_float("buoy_diameter", &buoy_diameter, 0.2f, 5, "the buoy's diameter, metres");
        p.add_float("buoy_density", &buoy_density, 50, 3000, "kg/m^3 (water: 1025)");
        p.add_float("raft_size", &raft_size, 1, 200, "the raft's side, metres");
        p.add_float("raft_density", &raft_density, 50, 3000, "kg/m^3");
        p.add_float("boat_length", &boat_length, 2, 60, "the boat's length (beam a third, depth a sixth), metres");
        p.add_float("boat_density", &boat_density, 50, 3000, "kg/m^3 of its closed hull");
        p.add_float("drag", &drag, 0, 5, "linear drag, per second per kilogram of water displaced");
        p.add_float("drop_height", &drop_height, -2, 10, "metres above the mean level the bodies are dropped from");
    }
};

struct Steering {
    float throttle = 0, rudder = 0;  // the panel's; the arrows add to them while held

    void declare(ocean::ParamRegistry& p) {
        const auto group = p.group("steering");
        p.add_float("boat_throttle", &throttle, -1, 1, "the boat's engine: 1 is full ahead (as the up arrow held), a thrust of 0.4 of its weight");
        p.add_float("boat_rudder", &rudder, -1, 1, "the boat's rudder: 1 is hard to starboard, its right (as the right arrow held)");
    }
};

}  // namespace step07
