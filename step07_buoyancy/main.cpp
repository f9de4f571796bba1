// step07_buoyancy: things that float on step06's sea.
// Beyond the notes. The sea is step06's: this program owns step06's frame (its SeaScene, with the
// Sea, the Sky, the SeaRenderer and the PostProcess) and runs it as step06's main.cpp does, drawing
// the bodies into the scene between the sea and the sky behind it; this chapter asks the sea
// questions. Each frame the maps the renderer draws reach the CPU (from the FFTW backend directly,
// or from the GPU through map_readback.hpp, a frame late: sea_feed.hpp), the height above each
// hull cell is found by inverting the choppy displacement (sea_query.hpp), and a buoy, a raft and
// a boat move under buoyancy and drag (floating_body.hpp).
// Controls: step06's; the arrows (held) steer the boat, a right click pushes the body under the
// cursor; the panel sets each body's size and density, drops them again, and sets the boat's
// throttle and rudder.
#include "common/app.hpp"
#include "step06_foam_sky/sea_scene.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/body_painter.hpp"
#include "step07_buoyancy/body_params.hpp"
#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/follow_camera.hpp"
#include "step07_buoyancy/query_grid.hpp"
#include "step07_buoyancy/sea_feed.hpp"
#include "step07_buoyancy/sea_query.hpp"

#include "common/error.hpp"
#include "common/file_output.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

namespace {

class Buoyancy : public ocean::App {
public:
    Buoyancy()
        : App({"Buoyancy", "",
               "step06's sea, read back: the height above a world point by inverting the choppy displacement, "
               "and bodies that float on it (buoyancy and drag over the hull's cells, semi-implicit Euler).",
               /*window_samples=*/0}) {
        ocean::ParamRegistry& p = params();
        // step06's parameters, then the bodies'.
        scene_.declare(p);
        body_params_.declare(p);  // a change drops the bodies again
        steering_.declare(p);       // read each frame: drops nothing
        follow_.declare(p);
        queries_.declare(p);
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_export([this](const std::string& dir) { export_all(dir); });
#ifndef OCEAN_GL_PORTABLE  // step05's backends: GL 4.5 only
        offer_bench_figures([this] { return scene_.sea().time_backends(time()); });
        offer_warm_up([this] { return scene_.sea().choosing_backend(); });
#endif
    }

private:
    void init() override {
        scene_.init(program_factory());
        queries_.init(program_factory());
        painter_.init(program_factory());
    }

    // step06's frame (sea_scene.hpp), then the bodies on the sea it made.
    void update(double time, double dt) override {
        scene_.update(time, dt, camera(), timers());
        ocean::GpuScope timed(timers(), "bodies");
        const auto started = std::chrono::steady_clock::now();
        feed_.update(scene_.sea(), time);
        read_input();  // every frame: a click before the first sea arrives is answered, not lost
        if (!feed_.ready()) return;
        if (bodies_made_for_ != body_params_.changes.value || bodies_.empty()) {
            bodies_made_for_ = body_params_.changes.value;
            drop_bodies();
        }
        steer_boat();
        const bool has_boat = bodies_.size() > step07::kBoat;
        const glm::dvec3 boat_before = has_boat ? bodies_[step07::kBoat].position() : glm::dvec3(0.0);
        step07::advance_bodies(bodies_, feed_.before(), feed_.now(), dt, feed_.interval());
        if (has_boat) follow_.follow(camera(), boat_before, bodies_[step07::kBoat].position());
        queries_.update(feed_.now(), scene_.sea(), camera().eye_world(), camera().forward(), time);
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            trajectory_.push_back({time, int(b), bodies_[b].position(), bodies_[b].orientation()});
        bodies_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    }

    // The three bodies, in front of the camera (anywhere on the ocean: positions in double).
    void drop_bodies() {
        trajectory_.clear();
        bodies_ = step07::drop_bodies(body_params_, camera());
    }

    // The panel's throttle and rudder, plus the arrows while they are held (bodies.hpp).
    void steer_boat() {
        if (bodies_.size() > step07::kBoat) step07::steer(bodies_[step07::kBoat], steering_, arrows_);
    }

    // step06's frame with the bodies and the query dots drawn into the scene between the sea (its
    // depth is there) and the sky behind it.
    void render() override {
        step06::FrameAdditions additions;
        additions.draw_into_scene = [this](const glm::mat4& view_projection) {
            const glm::dvec3 origin = scene_.sea().world_origin();
            queries_.draw(origin, view_projection);
            painter_.draw(bodies_, origin, view_projection, camera().eye_world(), scene_.sky(), scene_.look());
        };
        scene_.render({camera(), framebuffer_size(), aspect(), fullscreen_vao(), [this] { bind_target(); }},
                      timers(), additions);
    }

    // The keys and the mouse (windowed; each frame in update(), the panel shown or not): the arrows,
    // held, steer the boat; each right click pushes the body under the cursor away from the camera.
    void read_input() {
        arrows_ = step07::held_arrows();
        for (const ocean::InputEvent& press : frame_input().presses)
            if (press.code == ocean::input::kMouseRight) push_at(press.at);
    }

    // The body closest to the cursor's ray (common/camera.hpp), pushed where the ray passes it.
    void push_at(glm::dvec2 cursor) {
        const ImGuiIO& io = ImGui::GetIO();
        const std::optional<ocean::Ray> under_cursor = ocean::cursor_ray(
            camera(), aspect(), scene_.sea().world_origin(), cursor, {io.DisplaySize.x, io.DisplaySize.y});
        if (!under_cursor) return;
        if (bodies_.empty()) {
            std::cout << "push: the bodies are not dropped yet (they wait for the first sea)" << std::endl;
            return;
        }
        const glm::dvec3 from = under_cursor->from, ray = under_cursor->direction;
        step07::FloatingBody* hit = nullptr;
        double best = 0;
        glm::dvec3 at(0.0);
        for (auto& body : bodies_) {
            const glm::dvec3 closest = from + std::max(0.0, glm::dot(body.position() - from, ray)) * ray;
            const double miss = glm::length(body.position() - closest) / glm::length(body.settings().shape.size);
            if (miss < 1.0 && (hit == nullptr || miss < best)) hit = &body, best = miss, at = closest;
        }
        if (hit == nullptr) {
            std::cout << "push: no body under the cursor" << std::endl;
            return;
        }
        const double speed = step07::push_speed(*hit);  // about its own size in the first second
        const glm::dvec3 push = glm::normalize(glm::dvec3(ray.x, 0.0, ray.z) + glm::dvec3(1e-9, 0, 0));
        hit->push(speed * hit->mass() * push, at);  // at the point hit: it tilts as well
        std::cout << "push: the " << step07::kBodyNames[std::size_t(hit - bodies_.data()) % 3] << ", "
                  << std::round(speed * 10) / 10 << " m/s away from the camera" << std::endl;
    }

    void ui() override {
        ImGui::Separator();
        // Wrapped at the panel's edge, however narrow it is.
        ImGui::TextWrapped("bodies and queries: %.2f ms a frame; the maps %s", bodies_ms_,
                           feed_.latency_frames() == 0 ? "of this frame (FFTW)" : "read back, a frame late");
        ImGui::TextWrapped("arrows: steer the boat; right click: push a body");
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            ImGui::TextWrapped("%s: %.2f m above the mean level, %.0f%% under water, %.1f m/s", step07::kBodyNames[b % 3],
                               bodies_[b].position().y, 100 * bodies_[b].submerged_volume() / bodies_[b].volume(),
                               glm::length(bodies_[b].velocity()));
        if (ImGui::Button("drop again")) bodies_.clear();
        ImGui::SameLine();
        if (ImGui::Button("push the raft") && bodies_.size() > 1)
            bodies_[1].push(glm::dvec3(0, 0.5, 2) * bodies_[1].mass(),
                            bodies_[1].to_world({0.3 * body_params_.raft_size, 0.2, 0}));
    }

    // step06's export (the surface and foam; GL 4.5 only) and each body's trajectory, one row a
    // body a frame.
    void export_all(const std::string& dir) {
#ifndef OCEAN_GL_PORTABLE
        ocean::ProgramFactory programs = program_factory();
        scene_.sea().export_surface(dir, programs, time(), params());
#endif
        std::ostringstream out;
        out << "time,body,x,y,z,qw,qx,qy,qz\n";
        out.precision(10);
        for (const auto& r : trajectory_)
            out << r.time << ',' << r.body << ',' << r.position.x << ',' << r.position.y << ',' << r.position.z << ','
                << r.orientation.w << ',' << r.orientation.x << ',' << r.orientation.y << ',' << r.orientation.z << '\n';
        // Written whole, after the maps: the export is complete only if this succeeds too.
        if (auto error = ocean::write_file(std::filesystem::path(dir) / "trajectories.csv", out.str()))
            throw ocean::Error("--export: " + *error);
    }

    struct TrajectoryRow {
        double time;
        int body;
        glm::dvec3 position;
        glm::dquat orientation;
    };
    step06::SeaScene scene_;  // step06's frame
    // The bodies, and what asks the sea.
    std::vector<step07::FloatingBody> bodies_;
    std::vector<TrajectoryRow> trajectory_;
    step07::SeaFeed feed_;
    step07::BodyPainter painter_;
    unsigned bodies_made_for_ = 0;
    step07::BodyParams body_params_;
    step07::Steering steering_;
    // The camera kept on the boat from the start: a boat under way leaves a still view in seconds.
    step07::FollowCamera follow_;
    step07::Arrows arrows_;  // held this frame
    double bodies_ms_ = 0;
    step07::QueryGrid queries_;
};

}  // namespace

OCEAN_MAIN(Buoyancy)
