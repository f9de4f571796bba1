#include "step08_wakes/boat_and_wake.hpp"

#include "common/constants.hpp"
#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_query.hpp"
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_sea.hpp"

#include <algorithm>
#include <chrono>

namespace step08 {
namespace {

// The patch of the water the boat displaces afloat, its mass over the water's density
// (Archimedes): its weight is what presses. Not the volume under water at this instant, which
// swings as the boat heaves in the sea's waves (and is nothing while it falls on its drop):
// the patch would pulse and ring.
BoatSettings hull_patch(const step07::FloatingBody& boat) {
    return hull_of(boat.settings().shape.size.x, boat.mass() / step07::kWaterDensity);
}

// The hull's patch pressed on the field over dt, from where it was to where the boat is now.
void press(WakeScene& wake, const step07::FloatingBody& boat, double dt, const FieldStep& step = {}) {
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    wake.press(dt, {boat.position().x, boat.position().z}, {along.x, along.z}, hull_patch(boat), step);
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

BoatAndWake::BoatAndWake(std::unique_ptr<BodiesAndField> bodies_and_field)
    : bodies_and_field_(std::move(bodies_and_field)) {}

bool BoatAndWake::afloat_on(const WaveFieldSettings& field) const {
    return !bodies_.empty() && wake_ && same_grid(wake_settings_, field);
}

glm::dvec2 BoatAndWake::launch(std::vector<step07::FloatingBody> bodies, double throttle,
                               const WaveFieldSettings& field, double warm_up, const step07::SeaFeed& feed,
                               double choppiness) {
    bodies_ = std::move(bodies);
    step07::FloatingBody& boat = bodies_[step07::kBoat];
    const double speed =
        step07::kFullThrust * throttle * ocean::kGravity / std::max(boat.settings().linear_drag, 0.05);
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    const glm::dvec2 heading = glm::normalize(glm::dvec2(along.x, along.z));
    boat.push(boat.mass() * speed * glm::dvec3(heading.x, 0, heading.y), boat.position());
    // The raft abeam of the boat, 10 m off its course (step07 drops it where this boat, under
    // way, would sail through it): where the boat's wake reaches it a few seconds on. Put
    // afloat at its draft, not dropped, so that what rocks it is the wake.
    step07::FloatingBody& raft = bodies_[step07::kRaft];
    const glm::dvec2 beside = glm::dvec2(boat.position().x, boat.position().z) + 10.0 * glm::dvec2(-heading.y, heading.x);
    const step07::BodySettings& r = raft.settings();
    const double afloat = step07::query(feed.now(), beside).height + r.shape.size.y * (0.5 - r.density / step07::kWaterDensity);
    raft = step07::FloatingBody(r, {beside.x, afloat, beside.y}, raft.orientation());
    wake_settings_ = field;
    wake_ = std::make_unique<WakeScene>(wake_settings_);
    bodies_and_field_->field_made(*wake_, bodies_);
    BoatSettings hull = hull_patch(boat);
    hull.speed = speed;
    const glm::dvec2 at(boat.position().x, boat.position().z);
    wake_->place(at - warm_up * speed * heading, heading);
    wake_->sail(warm_up, hull, 0);
    wake_now_ = wake_maps(wake_->field(), choppiness);
    return heading;
}

// The boat floats on the sea without its wake: the hull's own depression is the water it
// displaces, which its buoyancy already counts. It then presses on the field along the way it
// went; the buoy and the raft float on the sea with the wake in it, the wake moving from last
// frame's to this frame's as the sea does. How the field and those bodies take the frame, and
// what of the field is drawn, is bodies_and_field_'s (step08's own is the above).
void BoatAndWake::sail(const SailFrame& frame) {
    const auto started = std::chrono::steady_clock::now();
    const step07::SeaFeed& feed = frame.feed;
    const double dt = frame.dt;
    step07::FloatingBody& boat = bodies_[step07::kBoat];
    step07::steer(boat, frame.steering, frame.arrows);
    boat.step(feed.before(), feed.now(), dt, feed.interval());
    WakeFrame field_frame{*wake_, bodies_, feed, frame.time, dt, frame.choppiness};
    drawing_ = frame.show_wake;
    if (!frame.show_wake) {
        // step07's sea: the field waits where the boat is, to take up from there.
        const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
        wake_->place({boat.position().x, boat.position().z}, {along.x, along.z});
        bodies_and_field_->let_go(field_frame);
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            if (b != step07::kBoat) bodies_[b].step(feed.before(), feed.now(), dt, feed.interval());
        wake_ms_ = 0;
        return;
    }
    bodies_and_field_->step_field(field_frame, [&](const FieldStep& step) { press(*wake_, boat, dt, step); });
    for (const glm::dvec2& stone : frame.stones) wake_->drop_stone(stone, frame.stone_impulse);
    wake_before_ = std::move(wake_now_);
    wake_now_ = bodies_and_field_->drawn_wake(field_frame);
    const SeaWithWake before(feed.before(), wake_before_), now(feed.now(), wake_now_);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (b != step07::kBoat && bodies_and_field_->rides_the_wake(field_frame, b))
            bodies_[b].step(before, now, dt, feed.interval());
    extra_waves_.upload(wake_now_);
    wake_ms_ = milliseconds_since(started);
}

std::vector<double> BoatAndWake::time_pressing(const step07::SeaFeed& feed, double choppiness) const {
    WakeScene scene = *wake_;
    std::vector<step07::FloatingBody> bodies = bodies_;
    step07::FloatingBody& boat = bodies[step07::kBoat];
    std::vector<double> times;
    bodies_and_field_->time_presses(scene, bodies, feed, [&](const FieldStep& step) {
        times = time_frames([&] {
            boat.step(feed.before(), feed.now(), 1.0 / 60, feed.interval());
            press(scene, boat, 1.0 / 60, step);
            wake_maps(scene.field(), choppiness);
        });
    });
    return times;
}

std::vector<double> time_frames(const std::function<void()>& frame) {
    std::vector<double> times;
    for (int i = 0; i < 15; ++i) {
        const auto start = std::chrono::steady_clock::now();
        frame();
        times.push_back(milliseconds_since(start));
    }
    return times;
}

}  // namespace step08
