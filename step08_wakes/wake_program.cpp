#include "step08_wakes/wake_program.hpp"

#include "common/error.hpp"
#include "common/gpu_timer.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_query.hpp"
#include "step08_wakes/wake_experiments.hpp"
#include "step08_wakes/wake_maps.hpp"
#include "step08_wakes/wake_sea.hpp"

#include <GLFW/glfw3.h>
#include <glm/gtc/quaternion.hpp>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

namespace step08 {
namespace {

// A moderate breeze (Beaufort 4): waves a metre high, a few whitecaps, and a wake that shows in
// them. step06's near gale would hide it.
constexpr double kBreeze = 6;

// The patch of the water the boat displaces afloat, its mass over the water's density
// (Archimedes): its weight is what presses. Not the volume under water at this instant, which
// swings as the boat heaves in the sea's waves (and is nothing while it falls on its drop):
// the patch would pulse and ring.
BoatSettings hull_patch(const step07::FloatingBody& boat) {
    return step08::hull_of(boat.settings().shape.size.x, boat.mass() / step07::kWaterDensity);
}

// The hull's patch pressed on the field over dt, from where it was to where the boat is now.
void press(WakeScene& wake, const step07::FloatingBody& boat, double dt, const FieldStep& step = {}) {
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    wake.press(dt, {boat.position().x, boat.position().z}, {along.x, along.z}, hull_patch(boat), step);
}

}  // namespace

WakeProgram::WakeProgram(ocean::StepInfo info, std::unique_ptr<BodiesAndField> bodies_and_field,
                         WakeProgramOptions options)
    : App(std::move(info)), bodies_and_field_(std::move(bodies_and_field)), options_(options) {
    body_params_.boat_length = 6;  // Froude number 0.5 at 4 m/s: a Kelvin wake
    steering_.throttle = 0.5f;     // about 4 m/s (the thrust against the hull's drag)
    ocean::ParamRegistry& p = params();
    sea_.declare(p);
    p.set_default("wind_speed", kBreeze);
    renderer_.declare(p);
    look_.declare(p);
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
        p.add_bool("follow_boat", &follow_boat_, "the camera keeps the boat where it is in the view");
        p.add_bool("show_wake", &show_wake_, "the wake added to the sea (off: step07's sea, which no body disturbs)");
        bodies_and_field_->declare(p);
    }
    if (options_.plan_view) plan_view_.declare(p);
    use_camera({{0, 0, 0}, 45, 35, 22}, ocean::kOceanReach);
    offer_bench_figures([this] { return bench_figures(); });
#ifndef OCEAN_GL_PORTABLE  // step05's backends: GL 4.5 only
    offer_warm_up([this] { return !plan_ && sea_.choosing_backend(); });
#endif
}

void WakeProgram::init() {
    sea_.init(program_factory());
    sky_ = std::make_unique<step06::Sky>(program_factory(), 128);
    renderer_.init(program_factory());
    post_.init(program_factory());
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
        plan_view_.update(dt, field_settings(), body_params_.boat_length, warm_up_, key_rudder_);
        for (const glm::dvec2& stone : stones_) plan_view_.drop_stone(stone);
        stones_.clear();
        return;
    }
    const glm::dvec3 eye = camera().eye_world();
    {
        ocean::GpuScope timed(timers(), "simulation");
        sea_.simulate(time, eye);
    }
    {
        ocean::GpuScope timed(timers(), "foam");
        sea_.update_foam(dt, eye, camera().forward());
    }
    {
        ocean::GpuScope timed(timers(), "sky");
        sky_->update(look_.sky(time, sea_.wind_direction()), look_.sky_image, look_.sky_image_changes.value);
    }
    ocean::GpuScope timed(timers(), "bodies and wake");
    feed_.update(sea_, time);
    if (!feed_.ready()) return;
    if (bodies_built_for_ != body_params_.changed.value || bodies_.empty() || !wake_ ||
        !step08::same_grid(wake_settings_, field_settings())) {
        drop_bodies_and_warm_up();
    }
    sail(std::min(dt, step07::kMaxBodyFrame));
}

// One frame of the bodies and the wake. The boat floats on the sea without its wake: the hull's
// own depression is the water it displaces, which its buoyancy already counts. It then presses
// on the field along the way it went; the buoy and the raft float on the sea with the wake in
// it, the wake moving from last frame's to this frame's as the sea does. How the field and those
// bodies take the frame, and what of the field is drawn, is bodies_and_field_'s (step08's own
// is the above).
void WakeProgram::sail(double dt) {
    const auto started = std::chrono::steady_clock::now();
    step07::FloatingBody& boat = bodies_[step07::kBoat];
    step07::steer(boat, double(steering_.throttle) + key_throttle_, double(steering_.rudder) + key_rudder_);
    const glm::dvec3 boat_before = boat.position();
    boat.step(feed_.before(), feed_.now(), dt, feed_.interval());
    if (follow_boat_) camera().target += glm::dvec3(boat.position().x - boat_before.x, 0, boat.position().z - boat_before.z);
    WakeFrame frame{*wake_, bodies_, feed_, time(), dt, sea_.choppiness()};
    if (!show_wake_) {
        // step07's sea: the field waits where the boat is, to take up from there.
        const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
        wake_->place({boat.position().x, boat.position().z}, {along.x, along.z});
        bodies_and_field_->let_go(frame);
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            if (b != step07::kBoat) bodies_[b].step(feed_.before(), feed_.now(), dt, feed_.interval());
        sea_.add_extra_waves(nullptr);
        stones_.clear();
        wake_ms_ = 0;
        return;
    }
    bodies_and_field_->step_field(frame, [&](const FieldStep& step) { press(*wake_, boat, dt, step); });
    for (const glm::dvec2& stone : stones_) wake_->drop_stone(stone);
    stones_.clear();
    wake_before_ = std::move(wake_now_);
    wake_now_ = bodies_and_field_->drawn_wake(frame);
    const step08::SeaWithWake before(feed_.before(), wake_before_), now(feed_.now(), wake_now_);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (b != step07::kBoat && bodies_and_field_->rides_the_wake(frame, b))
            bodies_[b].step(before, now, dt, feed_.interval());
    extra_waves_.upload(wake_now_);
    sea_.add_extra_waves(&extra_waves_);
    wake_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
}

// step07's bodies dropped in front of the camera; the boat already under way at the speed its
// throttle holds (thrust against drag), its wake made by `warm_up` seconds of sailing the
// same line, so the window opens on a wake.
void WakeProgram::drop_bodies_and_warm_up() {
    bodies_built_for_ = body_params_.changed.value;
    const glm::vec3 f = camera().forward();
    const glm::dvec2 ahead = glm::normalize(glm::dvec2(f.x, f.z) + glm::dvec2(1e-9, 0));
    bodies_ = step07::drop_bodies(body_params_, camera().eye_world(), ahead);
    step07::FloatingBody& boat = bodies_[step07::kBoat];
    const double speed = step07::kFullThrust * double(steering_.throttle) * ocean::kGravity /
                         std::max(double(body_params_.drag), 0.05);
    const glm::dvec3 along = boat.orientation() * glm::dvec3(1, 0, 0);
    const glm::dvec2 heading = glm::normalize(glm::dvec2(along.x, along.z));
    boat.push(boat.mass() * speed * glm::dvec3(heading.x, 0, heading.y), boat.position());
    // The raft abeam of the boat, 10 m off its course (step07 drops it where this boat, under
    // way, would sail through it): where the boat's wake reaches it a few seconds on. Put
    // afloat at its draft, not dropped, so that what rocks it is the wake.
    step07::FloatingBody& raft = bodies_[step07::kRaft];
    const glm::dvec2 beside = glm::dvec2(boat.position().x, boat.position().z) + 10.0 * glm::dvec2(-heading.y, heading.x);
    const step07::BodySettings& r = raft.settings();
    const double afloat = step07::query(feed_.now(), beside).height + r.shape.size.y * (0.5 - r.density / step07::kWaterDensity);
    raft = step07::FloatingBody(r, {beside.x, afloat, beside.y}, raft.orientation());
    wake_settings_ = field_settings();
    wake_ = std::make_unique<step08::WakeScene>(wake_settings_);
    bodies_and_field_->field_made(*wake_, bodies_);
    step08::BoatSettings hull = hull_patch(boat);
    hull.speed = speed;
    const glm::dvec2 at(boat.position().x, boat.position().z);
    wake_->place(at - double(warm_up_) * speed * heading, heading);
    wake_->sail(warm_up_, hull, 0);
    wake_now_ = step08::wake_maps(wake_->field(), sea_.choppiness());
    if (follow_boat_) look_from_behind(boat.position(), heading);
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
// draws 60 frames a second would spend it: a copy of the bodies and the field, the boat going
// straight on and pressing the field (in the field's steps bodies_and_field_ gives), the field's
// maps made each frame; and step05's backends as step07 times them.
ocean::App::BenchFigures WakeProgram::bench_figures() {
    BenchFigures figures;
#ifndef OCEAN_GL_PORTABLE
    if (!plan_) figures = sea_.time_backends(time());
#endif
    std::vector<double> times;
    const auto time_frames = [&times](auto&& frame) {
        for (int i = 0; i < 15; ++i) {
            const auto start = std::chrono::steady_clock::now();
            frame();
            times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
    };
    if (plan_ && plan_view_.scene() != nullptr) {
        step08::WakeScene scene = *plan_view_.scene();
        time_frames([&] { scene.sail(1.0 / 60, plan_view_.boat(), plan_view_.rudder()); });
    } else if (wake_ && !bodies_.empty() && feed_.ready()) {
        step08::WakeScene scene = *wake_;
        std::vector<step07::FloatingBody> bodies = bodies_;
        step07::FloatingBody& boat = bodies[step07::kBoat];
        try {
            bodies_and_field_->time_presses(scene, bodies, feed_, [&](const FieldStep& step) {
                time_frames([&] {
                    boat.step(feed_.before(), feed_.now(), 1.0 / 60, feed_.interval());
                    press(scene, boat, 1.0 / 60, step);
                    step08::wake_maps(scene.field(), sea_.choppiness());
                });
            });
        } catch (const ocean::Error& failure) {  // a step not taken: the run goes on, without this figure
            std::cerr << "warning: " << failure.what() << "; no wave_field_ms\n";
            return figures;
        }
    }
    figures.push_back({"wave_field_ms", ocean::median(times)});
    return figures;
}

// The arrows (held) steer the boat; a left click drops a stone where the cursor meets the sea.
void WakeProgram::read_input() {
    const ImGuiIO& io = ImGui::GetIO();
    key_throttle_ = key_rudder_ = 0;
    if (!io.WantCaptureKeyboard) {
        key_throttle_ = double(ImGui::IsKeyDown(GLFW_KEY_UP)) - double(ImGui::IsKeyDown(GLFW_KEY_DOWN));
        key_rudder_ = double(ImGui::IsKeyDown(GLFW_KEY_RIGHT)) - double(ImGui::IsKeyDown(GLFW_KEY_LEFT));
    }
    for (const ocean::InputEvent& press : frame_input().presses)
        if (press.code == ocean::input::kMouseLeft && !io.WantCaptureMouse) drop_stone_at(glm::dvec2(press.at));
}

void WakeProgram::drop_stone_at(glm::dvec2 cursor) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.DisplaySize.x <= 0 || io.DisplaySize.y <= 0) return;
    const glm::dvec2 uv(cursor.x / io.DisplaySize.x, 1 - cursor.y / io.DisplaySize.y);
    if (plan_) {
        stones_.push_back(plan_view_.to_world(uv, aspect()));
        return;
    }
    // The cursor's ray from the eye, to where it meets the mean level (y = 0).
    const glm::mat4 inverse = glm::inverse(camera().projection(aspect()) * camera().view(sea_.world_origin()));
    const glm::vec4 near = inverse * glm::vec4(2.0f * glm::vec2(uv) - 1.0f, -1, 1);
    const glm::vec4 far = inverse * glm::vec4(2.0f * glm::vec2(uv) - 1.0f, 1, 1);
    const glm::dvec3 from = sea_.world_origin() + glm::dvec3(glm::vec3(near) / near.w);
    const glm::dvec3 ray = glm::dvec3(glm::vec3(far) / far.w - glm::vec3(near) / near.w);
    if (!(ray.y < 0)) return;  // above the horizon: no sea there
    const glm::dvec3 hit = from - (from.y / ray.y) * ray;
    stones_.push_back({hit.x, hit.z});
}

void WakeProgram::render() {
    if (plan_) {
        clear_target({0, 0, 0});
        ocean::GpuScope timed(timers(), "wake");
        plan_view_.draw(aspect(), framebuffer_size().y, fullscreen_vao());
        return;
    }
    post_.begin(framebuffer_size());
    const glm::mat4 view_projection = camera().projection(aspect()) * camera().view(sea_.world_origin());
    {
        ocean::GpuScope timed(timers(), "ocean");
        renderer_.draw(sea_, *sky_, look_,
                       {view_projection, camera().eye_world(), framebuffer_size(), post_.scene_framebuffer(),
                        post_.depth_texture(), fullscreen_vao()});
    }
    painter_.draw(bodies_, sea_.world_origin(), view_projection, camera().eye_world(), *sky_, look_);
    {
        ocean::GpuScope timed(timers(), "background");
        sky_->draw_background(view_projection, fullscreen_vao());
    }
    const step06::PostSettings image = look_.post(renderer_.view() == step06::kViewShaded);
    {
        ocean::GpuScope timed(timers(), "bloom");
        post_.bloom(image, fullscreen_vao());
    }
    ocean::GpuScope timed(timers(), "tonemap");
    bind_target();
    post_.tonemap(image, fullscreen_vao());
}

void WakeProgram::ui() {
    ImGui::Separator();
    ImGui::TextWrapped("arrows: steer the boat; left click: drop a stone");
    if (!plan_ && bodies_and_field_->ui(bodies_, wake_ms_)) return;
    double speed = plan_view_.boat().speed, length = body_params_.boat_length;
    if (!plan_ && !bodies_.empty()) {
        const glm::dvec3 v = bodies_[step07::kBoat].velocity();
        speed = glm::length(glm::dvec2(v.x, v.z));
        ImGui::TextWrapped("the wake: %.2f ms a frame on the CPU", wake_ms_);
    }
    const double froude = step08::froude_number(speed, length);
    ImGui::TextWrapped("boat %.1f m/s; Froude number U / sqrt(g L) = %.2f; transverse waves %.1f m long", speed,
                       froude, step08::transverse_wavelength(speed));
    ImGui::TextWrapped("%s", froude < 0.5 ? "a Kelvin wake: its edge at 19.5 degrees"
                                          : "fast: the largest waves at a narrower angle, about 1 / Fr");
    if (plan_ && ImGui::Button("drop a stone ahead")) plan_view_.drop_stone_ahead();
}

}  // namespace step08
