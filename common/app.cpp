#include "common/app.hpp"

#include "common/error.hpp"
#include "common/gl_debug.hpp"
#include "common/image.hpp"
#include "common/panel_state.hpp"  // App owns one: its destructor needs the type
#include "common/run_support.hpp"
#include "common/text.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <filesystem>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

App::App(StepInfo info) : info_(std::move(info)) {}

App::~App() {
    programs_.clear();
    empty_vao_.reset();
    timers_ = GpuTimers();
    shutdown_imgui();
}

int App::run(int argc, char** argv, const StepLocation& where) {
    return run(std::vector<std::string>(argv + 1, argv + argc), where);
}

int App::run(const std::vector<std::string>& args, const StepLocation& where) {
    where_ = where;
    const ParseResult parsed = parse_command_line(args);
    auto fail = [](ExitCode code, const std::string& message) {
        std::cerr << "error: " << message << std::endl;
        return int(code);
    };
    if (parsed.error) return fail(kExitUsage, *parsed.error);
    const Options& options = parsed.options;
    if (options.help) {
        std::cout << usage_text(step_name(), info_.title + " (" + info_.notes_label() + ")");
        return kExitOk;
    }
    if (options.list_params) {
        std::cout << params_.list_text();
        return kExitOk;
    }
    if (!options.preset.empty())
        if (auto error = params_.load_preset(options.preset)) return fail(kExitUsage, *error);
    if (!options.camera.empty())
        if (auto error = apply_camera_preset(params_, options.camera)) return fail(kExitUsage, *error);
    split_view_ = options.split;
    for (const auto& assignment : options.sets)
        if (auto error = params_.set_assignment(assignment)) return fail(kExitUsage, *error);
    for (const auto& assignment : options.carries)  // only what this step has (Previous/Next)
        if (params_.find(trim(assignment.substr(0, assignment.find('=')))) != nullptr)
            if (auto error = params_.set_assignment(assignment)) return fail(kExitUsage, *error);
    if (!options.export_dir.empty() && !export_)
        return fail(kExitUsage, "--export: " + step_name() + " simulates no maps to export");
    if (!options.save_preset.empty()) {
        if (auto error = params_.save_preset(options.save_preset, step_name() + " preset"))
            return fail(kExitRuntimeError, *error);
        std::cout << "preset: " << options.save_preset << "\n";
        return kExitOk;
    }
    try {
        return run_loop(options);
    } catch (const Error& e) {
        return fail(kExitRuntimeError, e.what());
    }
}

float App::aspect() const {
    return framebuffer_size_.y > 0 ? float(framebuffer_size_.x) / float(framebuffer_size_.y) : 1.0f;
}

bool App::headless() const { return context_ && context_->headless(); }

void App::bind_target() const {
    glBindFramebuffer(GL_FRAMEBUFFER, context_->target_framebuffer());
    glViewport(0, 0, framebuffer_size_.x, framebuffer_size_.y);
}

void App::clear_target(glm::vec3 colour) const {
    glClearColor(colour.r, colour.g, colour.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void App::draw_fullscreen_triangle() const {
    glBindVertexArray(empty_vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void App::use_camera(const CameraView& view, double reach) {
    camera_.declare_params(params_, view, reach);
    camera_enabled_ = true;
}

int App::run_loop(const Options& options) {
    const bool headless = options.headless || !display_available();
    if (!options.headless && headless) std::cout << "no display: rendering headless\n";
    const std::string shader_dir = options.shader_dir.empty() ? where_.dir + "/shaders" : options.shader_dir;
    if (!fs::is_directory(shader_dir)) throw Error("shader directory '" + shader_dir + "' does not exist");
    programs_.set_shader_dir(where_.dir + "/shaders", shader_dir);

    context_ = Context::create({headless, options.width, options.height, step_name(), info_.window_samples});
    enable_gl_debug_output();
    std::cout << step_name() << ": " << context_->description() << "\n";
    empty_vao_ = make_vertex_array();
    all_steps_ = repository_steps();
    // --bench with a frame limit times the passes one by one (a glFinish around each) on the last
    // quarter of the frames only, and the frames per second on the frames before them
    // (FrameClock::stop); without a limit, every frame's passes.
    const int frame_limit = options.frames > 0 ? options.frames : (headless ? 10 : 0);
    const int pass_timed_frames = options.bench && frame_limit > 0 ? std::max(1, (frame_limit - 1) / 4) : 0;
    timers_.set_enabled(options.bench && pass_timed_frames == 0);
    framebuffer_size_ = context_->framebuffer_size();
    const bool draws_panel = !headless || options.show_ui;
    init_imgui(draws_panel);
    panel_visible_ = draws_panel && !options.hide_ui;
    init();

    FrameClock clock(options);
    time_ = clock.start_time();
    Image screenshot;
    int frame = 0;
    CloseOnSignal signals;
    const TestProbes probes(options);
    bool closed_early = false;
    for (; frame_limit == 0 || frame < frame_limit; ++frame) {
        context_->poll_events();
        if (context_->should_close() || signals.requested()) {
            closed_early = true;
            break;
        }
        const FrameClock::Tick tick = clock.tick(frame, paused_, warming_up_ && warming_up_());
        if (pass_timed_frames > 0 && frame == frame_limit - pass_timed_frames) {
            glFinish();  // the frames before it have finished: the clock's end
            clock.stop(frame);
            timers_.set_enabled(true);
        }
        if (frame > 0) time_ += tick.dt;
        if (tick.wall - last_reload_check_ > 0.5) {
            last_reload_check_ = tick.wall;
            programs_.reload_changed();
        }
        this->frame(probes, frame, tick.dt, tick.real_dt);
        const bool last = frame_limit > 0 && frame + 1 == frame_limit;
        if (!options.record_dir.empty()) record_frame(options.record_dir, frame);
        if (last && (!options.screenshot.empty() || headless)) screenshot = capture_frame(*context_, framebuffer_size_);
        context_->swap_buffers();
        timers_.collect();
        probes.after_frame(frame);
        programs_.set_running();  // a variant that fails to build from now on is shown, not fatal
    }
    // Closed before the last frame: a headless target still holds the last picture.
    if (closed_early && headless && frame > 0 && !options.screenshot.empty())
        screenshot = capture_frame(*context_, framebuffer_size_);
    write_outputs(options, screenshot, clock, frame);

    const GlDebugStats& gl = gl_debug_stats();
    if (gl.errors > 0 && headless) {
        std::cerr << "error: " << gl.errors << " OpenGL error(s) in a headless run; first: "
                  << gl.first_error << std::endl;
        return kExitGlError;
    }
    return kExitOk;
}

// One frame, in the order app.hpp documents: input, update, render (twice with the split view),
// the panel, then the caller presents.
void App::frame(const TestProbes& probes, int frame, double dt, double real_dt) {
    framebuffer_size_ = probes.framebuffer_size(*context_, frame, context_->framebuffer_size());
    begin_imgui_frame(dt);  // reads the keys and the mouse for ImGui
    read_input();           // after it: this frame's capture flags judge the queued events
    if (camera_enabled_) {
        camera_.apply(read_camera_input(), float(real_dt));
        if (frame_input_.drag_ended) report_camera();
    }

    update(time_, dt);
    const bool drawable = framebuffer_size_.x > 0 && framebuffer_size_.y > 0;  // zero while minimised
    if (drawable) {
        const auto render_frame = [this] {
            bind_target();
            render();
        };
        if (split_view_ && split_variants_) {
            if (auto error = split_.render(params_, split_variants_(), framebuffer_size_,
                                           context_->target_framebuffer(), render_frame))
                show_message(*error);
        } else {
            render_frame();
        }
    }
    draw_panel(float(real_dt * 1000.0));
    end_imgui_frame();
    // The panel, or with the panel hidden the split view's labels (which side is which).
    const bool overlay = panel_visible_ || (split_view_ && split_variants_);
    if (drawable && overlay && imgui_renderer_ready_) {
        bind_target();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    check_gl_errors("the frame");
}

}  // namespace ocean
