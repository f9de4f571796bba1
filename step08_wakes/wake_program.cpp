#include "step08_wakes/wake_program.hpp"

#include "common/error.hpp"
#include "common/gpu_timer.hpp"
#include "step08_wakes/wake_experiments.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

namespace step08 {
namespace {

// A moderate breeze (Beaufort 4): waves a metre high, a few whitecaps, and a wake that shows in
// them. step06's near gale would hide it.
constexpr double kBreeze = 6;

// A point on the water (x, z) as the stone lines print it: "(12.3, -4.5)".
std::string point_text(glm::dvec2 at) {
    char text[64];
    std::snprintf(text, sizeof text, "(%.1f, %.1f)", at.x, at.y);
    return text;
}

}  // namespace

WakeProgram::WakeProgram(ocean::StepInfo info, std::unique_ptr<BodiesAndField> bodies_and_field,
                         WakeProgramOptions options)
    : App(std::move(info)), options_(options), boat_and_wake_(std::move(bodies_and_field)) {
    body_params_.boat_length = 6;  // Froude number 0.5 at 4 m/s: a Kelvin wake
    steering_.throttle = 0.5f;     // about 4 m/s (the thrust against the hull's drag)
    ocean::ParamRegistry& p = params();
    scene_.declare(p);
    p.set_default("wind_speed", kBreeze);
    body_params_.declare(p);
    steering_.declare(p);
    {
        const auto group = p.group("wake");
        if (options_.plan_view)
            p.add_bool("plan", &plan_, "the wake alone, from above: a boat at boat_speed on still water");
        if (!options_.depth)
            p.add_float("depth", &depth_, 0.5f, 1000, "the water's depth under the wake, metres (1000: deep)").logarithmic();
        p.add_choice("cells", &cells_choice_, {"64", "128", "256"}, "the wave field's cells a side");
        p.add_float("cell", &cell_, 0.1f, 2, "the wave field's cell, metres");
        p.add_float("warm_up", &warm_up_, 0, 120, "seconds the boat has sailed before the first frame");
        p.add_float("stone_impulse", &stone_impulse_, 0.01f, 4,
                    "a clicked stone's impulse, its momentum over the water's density, m^4/s (2: a 200 kg boulder at 10 m/s)")
            .logarithmic();
        follow_.declare(p);
        p.add_bool("show_wake", &show_wake_, "the wake added to the sea (off: step07's sea, which no body disturbs)");
        boat_and_wake_.declare(p);
    }
    if (options_.plan_view) plan_view_.declare(p);
    use_camera({{0, 0, 0}, 45, 35, 22}, ocean::kOceanReach);
    offer_bench_figures([this] { return bench_figures(); });
#ifndef OCEAN_GL_PORTABLE  // step05's backends: GL 4.5 only
    offer_warm_up([this] { return !plan_ && scene_.sea().choosing_backend(); });
#endif
}

void WakeProgram::init() {
    scene_.init(program_factory());
    painter_.init(program_factory());
    if (options_.plan_view) plan_view_.init(program_factory());
}

WaveFieldSettings WakeProgram::field_settings() const {
    step08::WaveFieldSettings s;
    s.n = 64 << cells_choice_;
    s.cell = cell_;
    if (options_.depth)
        s.depth = *options_.depth;
    else
        s.depth = depth_ >= 1000 ? std::numeric_limits<double>::infinity() : double(depth_);
    s.absorbing_width = 0.125 * s.n * s.cell;  // an eighth of the side at each edge
    return s;
}

void WakeProgram::update(double time, double dt) {
    read_input();
    if (plan_) {
        plan_view_.update(dt, field_settings(), body_params_.boat_length, warm_up_, arrows_.rudder);
        for (const glm::dvec2& stone : stones_) plan_view_.drop_stone(stone, double(stone_impulse_));
        stones_.clear();
        return;
    }
    scene_.update(time, dt, camera(), timers());
    ocean::GpuScope timed(timers(), "bodies and wake");
    feed_.update(scene_.sea(), time);
    if (!feed_.ready()) return;
    if (bodies_made_for_ != body_params_.changes.value || !boat_and_wake_.afloat_on(field_settings()))
        drop_bodies_and_warm_up();
    sail(std::min(dt, step07::kMaxBodyFrame));
}

// One frame of the bodies and the wake (boat_and_wake.cpp), the camera following the boat, and
// the wake given to the sea to draw.
void WakeProgram::sail(double dt) {
    const glm::dvec3 boat_before = boat_and_wake_.bodies()[step07::kBoat].position();
    boat_and_wake_.sail({feed_, time(), dt, scene_.sea().choppiness(), steering_, arrows_, stones_, show_wake_,
                         double(stone_impulse_)});
    stones_.clear();
    const glm::dvec3 boat = boat_and_wake_.bodies()[step07::kBoat].position();
    follow_.follow(camera(), boat_before, boat);
    scene_.sea().add_extra_waves(boat_and_wake_.drawn_wake());
}

// step07's bodies dropped in front of the camera; the boat already under way at the speed its
// throttle holds (thrust against drag), its wake made by `warm_up` seconds of sailing the
// same line, so the window opens on a wake.
void WakeProgram::drop_bodies_and_warm_up() {
    bodies_made_for_ = body_params_.changes.value;
    const glm::dvec2 heading =
        boat_and_wake_.launch(step07::drop_bodies(body_params_, camera()), double(steering_.throttle),
                              field_settings(), double(warm_up_), feed_, scene_.sea().choppiness());
    if (follow_.on()) look_from_behind(boat_and_wake_.bodies()[step07::kBoat].position(), heading);
}

// The camera on the boat, from behind it and a little to port, high enough to see the wake's V
// open behind it (the view aerial photographs of wakes take).
void WakeProgram::look_from_behind(glm::dvec3 boat, glm::dvec2 heading) {
    ocean::Camera& c = camera();
    c.target = glm::dvec3(boat.x, 0, boat.z);
    // forward() is (sin yaw, -cos yaw) on the water: yaw along the heading, turned 20 degrees.
    c.yaw_deg = float(glm::degrees(std::atan2(heading.x, -heading.y))) + 20;
}

// --bench: the wake's CPU time per 1/60 s frame (median of 15, milliseconds), as a machine that
// draws 60 frames a second would spend it (BoatAndWake::time_pressing; in the plan view, the plan's
// boat sailing); and step05's backends as step07 times them.
ocean::App::BenchFigures WakeProgram::bench_figures() {
    BenchFigures figures;
#ifndef OCEAN_GL_PORTABLE
    if (!plan_) figures = scene_.sea().time_backends(time());
#endif
    std::vector<double> times;
    if (plan_ && plan_view_.scene() != nullptr) {
        step08::WakeScene scene = *plan_view_.scene();
        times = time_frames([&] { scene.sail(1.0 / 60, plan_view_.boat(), plan_view_.rudder()); });
    } else if (!boat_and_wake_.bodies().empty() && feed_.ready()) {
        try {
            times = boat_and_wake_.time_pressing(feed_, scene_.sea().choppiness());
        } catch (const ocean::Error& failure) {  // a step not taken: the run goes on, without this figure
            std::cerr << "warning: " << failure.what() << "; no wave_field_ms\n";
            return figures;
        }
    }
    figures.push_back({"wave_field_ms", ocean::median(times)});
    return figures;
}

// The arrows (held) steer the boat; a left click drops a stone where the cursor meets the sea. Each
// click says on stdout what became of it: a stone too small to see, or a click beside the field,
// would otherwise look like a click that did nothing.
void WakeProgram::read_input() {
    arrows_ = step07::held_arrows();
    const bool on_the_panel = ImGui::GetIO().WantCaptureMouse;
    for (const ocean::InputEvent& press : frame_input().presses)
        if (press.code == ocean::input::kMouseLeft && !on_the_panel) drop_stone_at(press.at);
}

void WakeProgram::drop_stone_at(glm::dvec2 cursor) {
    const glm::dvec2 window(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
    if (window.x <= 0 || window.y <= 0) return;
    if (plan_) {
        drop_stone(plan_view_.to_world({cursor.x / window.x, 1 - cursor.y / window.y}, aspect()));
        return;
    }
    // The cursor's ray (common/camera.hpp), to where it meets the mean level (y = 0).
    const auto ray = ocean::cursor_ray(camera(), aspect(), scene_.sea().world_origin(), cursor, window);
    if (!ray || !(ray->direction.y < 0)) {
        std::cout << "stone: the click is above the horizon, on the sky; not dropped" << std::endl;
        return;
    }
    const glm::dvec3 hit = ray->from - (ray->from.y / ray->direction.y) * ray->direction;
    drop_stone({hit.x, hit.z});
}

// A stone at `at` (x, z) for this frame's step, if the wave field is there to take it.
void WakeProgram::drop_stone(glm::dvec2 at) {
    const WakeScene* wake = plan_ ? plan_view_.scene() : boat_and_wake_.wake();
    if (wake == nullptr) {
        std::cout << "stone: the wave field is not made yet (it waits for the first sea); not dropped" << std::endl;
        return;
    }
    if (!wake->field().covers(at)) {
        std::cout << "stone: " << point_text(at) << " m is outside the wave field (the " << wake->field().side()
                  << " m square around the boat); not dropped" << std::endl;
        return;
    }
    if (!plan_ && !show_wake_) {
        std::cout << "stone: the wake is off (show_wake=false); not dropped" << std::endl;
        return;
    }
    stones_.push_back(at);
    std::cout << "stone: dropped at " << point_text(at) << " m, " << stone_impulse_ << " m^4/s" << std::endl;
}

void WakeProgram::render() {
    if (plan_) {
        clear_target({0, 0, 0});
        ocean::GpuScope timed(timers(), "wake");
        plan_view_.draw(aspect(), framebuffer_size().y, fullscreen_vao());
        return;
    }
    step06::FrameAdditions additions;
    additions.draw_into_scene = [this](const glm::mat4& view_projection) {
        painter_.draw(boat_and_wake_.bodies(), scene_.sea().world_origin(), view_projection, camera().eye_world(),
                      scene_.sky(), scene_.look());
    };
    scene_.render({camera(), framebuffer_size(), aspect(), fullscreen_vao(), [this] { bind_target(); }}, timers(),
                  additions);
}

void WakeProgram::ui() {
    ImGui::Separator();
    ImGui::TextWrapped("arrows: steer the boat; left click: drop a stone");
    if (!plan_ && boat_and_wake_.ui()) return;
    double speed = plan_view_.boat().speed, length = body_params_.boat_length;
    if (!plan_ && !boat_and_wake_.bodies().empty()) {
        const glm::dvec3 v = boat_and_wake_.bodies()[step07::kBoat].velocity();
        speed = glm::length(glm::dvec2(v.x, v.z));
        ImGui::TextWrapped("the wake: %.2f ms a frame on the CPU", boat_and_wake_.wake_ms());
    }
    const double froude = step08::froude_number(speed, length);
    ImGui::TextWrapped("boat %.1f m/s; Froude number U / sqrt(g L) = %.2f; transverse waves %.1f m long", speed,
                       froude, step08::transverse_wavelength(speed));
    ImGui::TextWrapped("%s", froude < 0.5 ? "a Kelvin wake: its edge at 19.5 degrees"
                                          : "fast: the largest waves at a narrower angle, about 1 / Fr");
    if (plan_ && plan_view_.scene() != nullptr && ImGui::Button("drop a stone ahead"))
        drop_stone(plan_view_.scene()->boat_position() + 10.0 * plan_view_.scene()->boat_heading());
}

}  // namespace step08
