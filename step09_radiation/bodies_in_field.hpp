// Chapter 9 in the program: step07's bodies moved with step08's field, in its own steps. step08's
// WakeScene cuts a frame into steps in which the boat moves at most a cell; each of them is taken
// here instead of by the field alone: the buoy reads the field and puts in its sources, the raft
// is in contact, and the field steps with both and the boat's pressure.
#pragma once

#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_surface.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step09_radiation/contact_step.hpp"
#include "step09_radiation/radiating_buoy.hpp"

#include <vector>

namespace step09 {

// A buoy and its sources (radiating_buoy.hpp).
struct Radiating {
    step07::FloatingBody* body = nullptr;
    RadiatingBuoy* sources = nullptr;
};

// The bodies one frame moves with the field: those in contact (such as can_touch takes), those
// radiating (such as their sources hold for), and the incident sea at the frame's start and end.
struct BodiesInField {
    std::vector<step07::FloatingBody*> in_contact;
    std::vector<Radiating> radiating;
    const step07::Surface* before = nullptr;
    const step07::Surface* now = nullptr;
    double sea_interval = 0;  // seconds between those two seas
};

// The step step08's WakeScene::press takes with `bodies`: over the share `from` to `to` of the
// frame, the buoys move first and add their sources to the forcing, then the field steps with the
// contact of the bodies in it (`contact` keeps its kernel and the pressure it held). Both must
// outlive the step it returns.
step08::FieldStep step_with(const BodiesInField& bodies, ContactStep& contact);

}  // namespace step09
