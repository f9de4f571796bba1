// Chapter 8 in the program: how the wave field and the bodies other than the boat take a frame, and
// what of the field the sea draws. This class is step08's own way (its defaults): the boat's hull
// presses the field, the buoy and the raft float on the sea with the wake in it, the field is
// drawn as it is. BoatAndWake (boat_and_wake.hpp), the physics of WakeProgram's frame, asks this
// class at each of these points, so a program that moves other bodies with the field gives
// WakeProgram a subclass and leaves the rest of the frame (the sea, the boat, the camera, the
// drawing) as step08's.
#pragma once

#include "common/params.hpp"
#include "step06_foam_sky/extra_waves.hpp"
#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_feed.hpp"
#include "step08_wakes/wake_scene.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace step08 {

// What a frame of the bodies and the field works on: the program's own, lent for the call.
struct WakeFrame {
    WakeScene& wake;
    std::vector<step07::FloatingBody>& bodies;  // step07's, the boat at step07::kBoat
    const step07::SeaFeed& feed;                // the sea at the frame's start (before) and end (now)
    double time = 0, dt = 0;                    // the program's clock; the bodies' step, seconds
    double choppiness = 0;                      // the sea's, which the wake's maps take
};

class BodiesAndField {
public:
    // Presses the boat's hull on the field over the frame; a FieldStep given takes the field's
    // steps in its place (wake_scene.hpp), an empty one lets the field step alone.
    using Press = std::function<void(const FieldStep& step)>;

    virtual ~BodiesAndField() = default;

    // Its own parameters, declared in the "wake" group after step08's.
    virtual void declare(ocean::ParamRegistry& /*params*/) {}
    // A new field around bodies just dropped, before the warm-up sails the boat through it.
    virtual void field_made(const WakeScene& /*wake*/, const std::vector<step07::FloatingBody>& /*bodies*/) {}
    // One frame of the field, the boat's press in it (`press`); the boat has already moved.
    virtual void step_field(WakeFrame& /*frame*/, const Press& press) { press({}); }
    // Whether `body` (not the boat) then floats on the sea with the wake in it; false for one
    // step_field moved with the field.
    virtual bool rides_the_wake(const WakeFrame& /*frame*/, std::size_t /*body*/) const { return true; }
    // The field's maps as the sea draws them.
    virtual step06::ExtraWaveMaps drawn_wake(const WakeFrame& frame) const;
    // The wake turned off (show_wake=false): the field waits, and the bodies (not the boat) float
    // on step07's sea after this.
    virtual void let_go(WakeFrame& /*frame*/) {}
    // --bench: runs `time` (which times frames of the boat pressing the copy `wake`) with the
    // field's step as step_field gives it, on the copy `bodies`; what it sets up once is made here,
    // outside the timed frames.
    virtual void time_presses(const WakeScene& /*wake*/, std::vector<step07::FloatingBody>& /*bodies*/,
                              const step07::SeaFeed& /*feed*/, const Press& time) {
        time({});
    }
    // Its own lines in the panel, in the place of step08's boat speed and Froude number: true if
    // it wrote them.
    virtual bool ui(const std::vector<step07::FloatingBody>& /*bodies*/, double /*wake_ms*/) const {
        return false;
    }
};

}  // namespace step08
