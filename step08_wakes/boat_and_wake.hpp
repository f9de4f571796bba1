// Chapter 8's physics as the program runs it, frame by frame: step07's bodies on the sea the
// program reads (a SeaFeed), the boat's hull and the stones pressing the wave field around it, and
// the field's maps for the sea to draw. WakeProgram (wake_program.hpp) owns one, gives it the sea,
// the steering and the clock each frame, and draws what it holds; --bench times its boat pressing
// the field (time_pressing) with the same press.
// How the field and the bodies other than the boat take a frame is the BodiesAndField it is given
// (bodies_and_field.hpp).
#pragma once

#include "common/params.hpp"
#include "step06_foam_sky/extra_waves.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_feed.hpp"
#include "step08_wakes/bodies_and_field.hpp"
#include "step08_wakes/wake_scene.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace step08 {

// One frame of sailing, as the program gives it.
struct SailFrame {
    const step07::SeaFeed& feed;  // the sea at the frame's start (before) and end (now)
    double time = 0, dt = 0;      // the program's clock; the bodies' step, seconds
    double choppiness = 0;        // the sea's, which the wake's maps take
    step07::Steering steering;    // the panel's throttle and rudder,
    step07::Arrows arrows;        // and the arrows held
    const std::vector<glm::dvec2>& stones;  // dropped this frame (x, z)
    bool show_wake = true;  // false: step07's sea, the field waiting where the boat is
    double stone_impulse = kStoneImpulse;  // each stone's, m^4/s (wake_scene.hpp)
};

class BoatAndWake {
public:
    explicit BoatAndWake(std::unique_ptr<BodiesAndField> bodies_and_field);

    // The BodiesAndField's own parameters, and its lines in the panel (true if it wrote them).
    void declare(ocean::ParamRegistry& p) { bodies_and_field_->declare(p); }
    bool ui() const { return bodies_and_field_->ui(bodies_, wake_ms_); }

    // Whether bodies are afloat on a field of `field`'s grid; if not, launch() puts them there.
    bool afloat_on(const WaveFieldSettings& field) const;
    // step07's three `bodies`, just dropped, put to sea: the boat under way at the speed `throttle`
    // holds against its drag, the raft afloat 10 m abeam of it on the sea `feed` has now, and a
    // new field of `field`'s grid around the boat holding the wake of `warm_up` seconds of sailing
    // the same line. Returns the boat's heading (x, z; unit).
    glm::dvec2 launch(std::vector<step07::FloatingBody> bodies, double throttle, const WaveFieldSettings& field,
                      double warm_up, const step07::SeaFeed& feed, double choppiness);
    // One frame of the bodies and the wake (launch() first).
    void sail(const SailFrame& frame);

    // The wake for the sea to draw after the last sail(), or none when the wake is off.
    const step06::ExtraWaves* drawn_wake() const { return drawing_ ? &extra_waves_ : nullptr; }
    const std::vector<step07::FloatingBody>& bodies() const { return bodies_; }
    const WakeScene* wake() const { return wake_.get(); }  // none before launch()
    double wake_ms() const { return wake_ms_; }  // the last sail()'s, on the CPU

    // --bench: the CPU milliseconds of 15 frames of 1/60 s, each the boat going straight on and
    // pressing the field (in the field's steps the BodiesAndField gives) and the field's maps made,
    // on a copy of the bodies and the field. Throws ocean::Error if a step cannot be taken.
    std::vector<double> time_pressing(const step07::SeaFeed& feed, double choppiness) const;

private:
    const std::unique_ptr<BodiesAndField> bodies_and_field_;
    std::vector<step07::FloatingBody> bodies_;  // step07's, the boat at step07::kBoat
    // The wake: its field, its maps last frame and now, and the textures step06's shaders read.
    std::unique_ptr<WakeScene> wake_;
    WaveFieldSettings wake_settings_;
    step06::ExtraWaveMaps wake_before_, wake_now_;
    step06::ExtraWaves extra_waves_;
    bool drawing_ = false;  // the last sail() showed the wake
    double wake_ms_ = 0;
};

// --bench's frames: the CPU milliseconds of each of 15 calls of `frame`.
std::vector<double> time_frames(const std::function<void()>& frame);

}  // namespace step08
