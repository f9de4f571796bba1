// step09_radiation: bodies that make the waves that damp them, on step08's wake and step06's sea.
// Beyond the notes. The program is step08's (step06's sea, sky, renderer and post-processing,
// step07's bodies, step08's wave field pressed by the boat and drawn on the sea), with step07's
// raft in contact with the field (hull_contact.hpp: the water under its bottom ends each step where
// the bottom is, and pushes it with the pressure that takes) and the buoy radiating (radiating_buoy.hpp:
// sources on its wetted surface, Green's identity for the water they put through the surface).
// `buoy_waves=false` lets both float on step07's Archimedes as in step08; `forced_heave` moves
// the buoy up and down to watch its rings.
// The program is step08's (wake_program.hpp), given this chapter's way for the bodies and the
// field to take a frame (RadiatingBodies below, a step08::BodiesAndField); no plan view, deep water.
// Controls: step08's; the arrows (held) steer the boat; a left click drops a stone.
#include "common/app.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step08_wakes/bodies_and_field.hpp"
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_program.hpp"
#include "step09_radiation/bodies_in_field.hpp"
#include "step09_radiation/hull_contact.hpp"

#include <imgui.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

namespace {

// The raft in contact with the field and the buoy radiating: they move in the field's own steps,
// making their waves, where step08's ride the wake. (step08 puts the raft afloat at its draft, not
// dropped, within the field: a 5 m raft falling 1.5 m flat on the water would splash the view white
// with its rings.)
class RadiatingBodies : public step08::BodiesAndField {
public:
    void declare(ocean::ParamRegistry& p) override {
        p.add_bool("buoy_waves", &buoy_waves_, "the raft and the buoy make waves as they move (off: they ride the wake on step07's Archimedes, as in step08)");
        p.add_float("forced_heave", &forced_heave_, 0, 0.5, "a push up and down on the buoy at 1 Hz, its weight times this (0: none)");
    }

    void field_made(const step08::WakeScene& wake, const std::vector<step07::FloatingBody>& bodies) override {
        try {
            buoy_sources_ = std::make_unique<step09::RadiatingBuoy>(wake.field(), bodies[step07::kBuoy]);
        } catch (const ocean::Error& failure) {
            // A buoy as dense as the water (it sinks) or too large for the grid has no sources: it
            // rides the wake on step07's Archimedes.
            std::cerr << "warning: " << failure.what() << "; the buoy rides the wake without making waves\n";
            buoy_sources_.reset();
        }
    }

    // The wake turned off: the bodies the field held float on step07's Archimedes again, their
    // dents taken out of the field.
    void let_go(step08::WakeFrame& frame) override {
        std::vector<step07::FloatingBody>& bodies = frame.bodies;
        step08::WaveField& field = frame.wake.field();
        if (buoy_sources_) buoy_sources_->let_go(bodies[step07::kBuoy]);
        for (std::size_t b = 0; b < bodies.size(); ++b)
            if (b != step07::kBoat) {
                if (!bodies[b].archimedes()) step09::lift_out(field, bodies[b], frame.feed.before());
                bodies[b].set_archimedes(true);
            }
    }

    // One frame of the bodies and the wake, step08's with the raft in contact and the buoy
    // radiating. The boat floats on the sea without its wake and presses on the field along the
    // way it went (step08); the raft and the buoy move in the same steps as the field, making
    // their waves; a body the field cannot hold floats on the sea with the wake in it.
    void step_field(step08::WakeFrame& frame, const Press& press) override {
        std::vector<step07::FloatingBody>& bodies = frame.bodies;
        step08::WaveField& field = frame.wake.field();
        // The raft, within the field, in contact with it, and the buoy afloat within it, radiating.
        step09::BodiesInField in_field{{}, {}, &frame.feed.before(), &frame.feed.now(), frame.feed.interval()};
        step07::FloatingBody& buoy = bodies[step07::kBuoy];
        if (forced_heave_ > 0)  // an impulse each frame: the buoy's weight times forced_heave, at 1 Hz
            buoy.push({0, buoy.mass() * ocean::kGravity * double(forced_heave_) * std::sin(ocean::kTwoPi * frame.time) * frame.dt, 0},
                      buoy.position());
        const bool radiating = buoy_radiating_ = buoy_radiates(field, buoy, frame.feed.before());
        if (radiating)
            in_field.radiating.push_back({&buoy, buoy_sources_.get()});
        else if (buoy_sources_)
            buoy_sources_->let_go(buoy);
        for (std::size_t b = 0; b < bodies.size(); ++b) {
            const bool contact = buoy_waves_ && b != step07::kBoat && step09::can_touch(field, bodies[b]);
            // A body coming into the field brings its dent with it: the water under it settled
            // where its hull is, as Archimedes held it (else the first step would push it all in);
            // one leaving takes its dent away (else the dent would fall back as a ring of waves).
            if (contact && bodies[b].archimedes()) step09::settle_under(field, bodies[b], frame.feed.before());
            if (!contact && !bodies[b].archimedes()) step09::lift_out(field, bodies[b], frame.feed.before());
            bodies[b].set_archimedes(!contact);
            if (contact) in_field.in_contact.push_back(&bodies[b]);
        }
        try {
            press(step09::step_with(in_field, contact_));
        } catch (const ocean::Error& failure) {
            // Should a contact's system still be singular, the frame goes on without it: its bodies
            // float on Archimedes (and try again next frame), rather than the program stopping.
            if (!contact_failed_) std::cerr << "warning: " << failure.what() << "; the bodies in contact float on Archimedes this frame\n";
            contact_failed_ = true;
            contact_.release();
            for (step07::FloatingBody* body : in_field.in_contact) {
                step09::lift_out(field, *body, frame.feed.before());
                body->set_archimedes(true);
            }
        }
    }

    // The bodies step_field moved with the field (the raft in contact, the buoy radiating) do not.
    bool rides_the_wake(const step08::WakeFrame& frame, std::size_t b) const override {
        return frame.bodies[b].archimedes() && !(b == step07::kBuoy && buoy_radiating_);
    }

    // The field's maps as the window shows it: beside the bodies in contact, their dents (the water
    // under a hull, which the hull hides) left out, their waves kept (contact_step.hpp's pressure).
    step06::ExtraWaveMaps drawn_wake(const step08::WakeFrame& frame) const override {
        if (contact_.pressure().empty()) return step08::wake_maps(frame.wake.field(), frame.choppiness);
        std::vector<double> heights = frame.wake.field().heights();
        for (std::size_t c = 0; c < heights.size(); ++c) heights[c] += contact_.pressure()[c] / ocean::kGravity;
        return step08::wake_maps(frame.wake.field(), frame.choppiness, &heights);
    }

    // --bench: the raft in contact with the field when it is, the buoy radiating when it does,
    // with a contact of their own and a copy of the buoy's sources.
    void time_presses(const step08::WakeScene& wake, std::vector<step07::FloatingBody>& bodies,
                      const step07::SeaFeed& feed, const Press& time) override {
        step09::BodiesInField in_field{{}, {}, &feed.before(), &feed.now(), feed.interval()};
        step09::ContactStep contact;
        for (std::size_t b = 0; b < bodies.size(); ++b)
            if (b != step07::kBoat && !bodies[b].archimedes()) in_field.in_contact.push_back(&bodies[b]);
        std::unique_ptr<step09::RadiatingBuoy> sources;
        if (buoy_radiates(wake.field(), bodies[step07::kBuoy], feed.before())) {
            sources = std::make_unique<step09::RadiatingBuoy>(*buoy_sources_);
            in_field.radiating.push_back({&bodies[step07::kBuoy], sources.get()});
        }
        time(step09::step_with(in_field, contact));
    }

    bool ui(const std::vector<step07::FloatingBody>& bodies, double wake_ms) const override {
        if (bodies.empty()) return true;
        ImGui::TextWrapped("the wake and the bodies: %.2f ms a frame on the CPU", wake_ms);
        const step07::FloatingBody &raft = bodies[step07::kRaft], &buoy = bodies[step07::kBuoy];
        ImGui::TextWrapped("raft: %s", raft.archimedes() ? "on step07's Archimedes" : "in contact with the field");
        ImGui::TextWrapped("buoy: %s, heaving at %.2f m/s", buoy_radiating_ ? "radiating" : "on step07's Archimedes",
                           buoy.velocity().y);
        return true;
    }

private:
    // Whether the buoy makes waves this frame: switched on, with sources, and as they hold for it.
    bool buoy_radiates(const step08::WaveField& field, const step07::FloatingBody& buoy,
                       const step07::Surface& sea) const {
        return buoy_waves_ && buoy_sources_ && buoy_sources_->holds(field, buoy, sea);
    }

    // The bodies' waves: the raft's contact (its kernel, the pressure it held), the buoy's sources.
    step09::ContactStep contact_;
    std::unique_ptr<step09::RadiatingBuoy> buoy_sources_;  // the buoy's, for the field's grid
    bool buoy_waves_ = true, buoy_radiating_ = false;
    bool contact_failed_ = false;  // warned once
    float forced_heave_ = 0;
};

// Deep water: the sources' images and their waves (source_hull.hpp) are deep water's.
constexpr double kDeepWater = std::numeric_limits<double>::infinity();

class Radiation : public step08::WakeProgram {
public:
    Radiation()
        : WakeProgram({"Radiation", "",
                       "Bodies that make the waves that damp them, on step08's wake: the raft in contact with the wave "
                       "field (the water under it ends each step where its bottom is), the buoy as sources on its "
                       "wetted surface that radiate its heave away as rings. Arrows: steer the boat; left click: drop "
                       "a stone.",
                       /*window_samples=*/0},
                      std::make_unique<RadiatingBodies>(),
                      step08::WakeProgramOptions{/*plan_view=*/false, /*depth=*/kDeepWater}) {}
};

}  // namespace

OCEAN_MAIN(Radiation)
