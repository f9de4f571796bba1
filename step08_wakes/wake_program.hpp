// Chapter 8's program: step06's frame (its SeaScene: the sea, sky, renderer and post-processing),
// step07's bodies and the feed of the sea they float on, and the wave field around step07's boat,
// pressed by its hull and by stones dropped with a click, drawn on the sea (main.cpp tells the
// story). The frame reads top to bottom here; the physics of each frame is a BoatAndWake's
// (boat_and_wake.hpp), and how the field and the bodies other than the boat take it is a
// BodiesAndField (bodies_and_field.hpp), so a program that moves them otherwise keeps the rest as
// it is.
#pragma once

#include "common/app.hpp"
#include "step06_foam_sky/sea_scene.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/body_painter.hpp"
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/follow_camera.hpp"
#include "step07_buoyancy/sea_feed.hpp"
#include "step08_wakes/boat_and_wake.hpp"
#include "step08_wakes/bodies_and_field.hpp"
#include "step08_wakes/plan_view.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace step08 {

// What of step08's program a program built on it keeps.
struct WakeProgramOptions {
    bool plan_view = true;        // `plan`: the wake alone, from above (the lesson's laboratory)
    std::optional<double> depth;  // the field's depth, fixed; unset: the `depth` parameter
};

class WakeProgram : public ocean::App {
public:
    WakeProgram(ocean::StepInfo info, std::unique_ptr<BodiesAndField> bodies_and_field,
                WakeProgramOptions options = {});

private:
    void init() override;
    void update(double time, double dt) override;
    void render() override;
    void ui() override;

    WaveFieldSettings field_settings() const;
    void sail(double dt);
    void drop_bodies_and_warm_up();
    void look_from_behind(glm::dvec3 boat, glm::dvec2 heading);
    BenchFigures bench_figures();
    void read_input();
    void drop_stone_at(glm::dvec2 cursor);
    void drop_stone(glm::dvec2 at);

    const WakeProgramOptions options_;
    step06::SeaScene scene_;  // step06's frame
    // step07's bodies and the sea they float on, and the wake: the frame's physics.
    step07::SeaFeed feed_;
    BoatAndWake boat_and_wake_;
    step07::BodyPainter painter_;
    step07::BodyParams body_params_;
    step07::Steering steering_;
    unsigned bodies_made_for_ = 0;
    PlanView plan_view_;
    step07::FollowCamera follow_;  // the camera kept on the boat, under way from the start
    bool plan_ = false, show_wake_ = true;
    float depth_ = 1000, cell_ = 0.5, warm_up_ = 20;
    float stone_impulse_ = float(kStoneImpulse);  // m^4/s
    int cells_choice_ = 1;
    step07::Arrows arrows_;           // held this frame
    std::vector<glm::dvec2> stones_;  // clicked on the field, for this frame's step
};

}  // namespace step08
