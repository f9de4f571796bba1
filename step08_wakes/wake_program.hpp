// Chapter 8's program: step06's sea, sky, renderer and post-processing, step07's bodies and the
// feed of the sea they float on, and the wave field around step07's boat, pressed by its hull and
// by stones dropped with a click, drawn on the sea (main.cpp tells the story). The frame reads top
// to bottom here; how the field and the bodies other than the boat take it is a BodiesAndField
// (bodies_and_field.hpp), so a program that moves them otherwise keeps the rest as it is.
#pragma once

#include "common/app.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/sea_renderer.hpp"
#include "step06_foam_sky/sky.hpp"
#include "step07_buoyancy/body_painter.hpp"
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_feed.hpp"
#include "step08_wakes/bodies_and_field.hpp"
#include "step08_wakes/plan_view.hpp"
#include "step08_wakes/wake_scene.hpp"

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

    const std::unique_ptr<BodiesAndField> bodies_and_field_;
    const WakeProgramOptions options_;
    // step06's parts.
    step06::Sea sea_;
    std::unique_ptr<step06::Sky> sky_;
    step06::SeaRenderer renderer_;
    step06::PostProcess post_;
    step06::LookParams look_;
    // step07's bodies.
    std::vector<step07::FloatingBody> bodies_;
    step07::SeaFeed feed_;
    step07::BodyPainter painter_;
    step07::BodyParams body_params_;
    step07::Steering steering_;
    unsigned bodies_built_for_ = 0;
    // The wake: its field, its maps last frame and now, and the textures step06's shaders read.
    std::unique_ptr<WakeScene> wake_;
    WaveFieldSettings wake_settings_;
    step06::ExtraWaveMaps wake_before_, wake_now_;
    step06::ExtraWaves extra_waves_;
    PlanView plan_view_;
    bool plan_ = false, follow_boat_ = true, show_wake_ = true;
    float depth_ = 1000, cell_ = 0.5, warm_up_ = 20;
    int cells_choice_ = 1;
    double key_throttle_ = 0, key_rudder_ = 0;  // the arrows, held
    std::vector<glm::dvec2> stones_;
    double wake_ms_ = 0;
};

}  // namespace step08
