#include "common/app.hpp"

#include "common/error.hpp"
#include "common/gl_debug.hpp"
#include "common/image.hpp"
#include "common/panel_state.hpp"  // App owns one: its destructor needs the type
#include "common/run_support.hpp"
#include "common/text.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

#include <filesystem>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

// What the frame loop keeps from one frame to the next: run_loop's state, held by the App so that
// a browser, which calls the loop one frame at a time, finds it between two calls.
struct App::FrameLoop {
    FrameLoop(const Options& run_options, bool run_headless, int limit, int timed)
        : options(run_options), headless(run_headless), frame_limit(limit), pass_timed_frames(timed),
          clock(run_options), probes(run_options) {}
    const Options options;
    const bool headless;
    const int frame_limit;        // 0: until the window closes
    const int pass_timed_frames;  // --bench: the last frames, whose passes are timed one by one
    FrameClock clock;
    TestProbes probes;
    CloseOnSignal signals;
    Image screenshot;
    int frame = 0;
    bool closed_early = false;
};

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
    paused_ = options.paused;
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
    // A chapter may have no shaders of its own (it draws with earlier chapters'): only a folder given
    // with --shader-dir must exist.
    if (!options.shader_dir.empty() && !fs::is_directory(shader_dir))
        throw Error("shader directory '" + shader_dir + "' does not exist");
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

    loop_ = std::make_unique<FrameLoop>(options, headless, frame_limit, pass_timed_frames);
    time_ = loop_->clock.start_time();
#if defined(__EMSCRIPTEN__)
    // A page hands each frame to the browser as a callback (its own frame loop), so that the
    // browser shows the frame and runs its events in between; this call does not return.
    emscripten_set_main_loop_arg(&App::browser_frame, this, 0, true);
#endif
    while (loop_turn()) {
    }
    return finish_loop();
}

bool App::loop_turn() {
    FrameLoop& loop = *loop_;
    if (loop.frame_limit > 0 && loop.frame >= loop.frame_limit) return false;
    context_->poll_events();
    if (context_->should_close() || loop.signals.requested()) {
        loop.closed_early = true;
        return false;
    }
    const int frame = loop.frame;
    const FrameClock::Tick tick = loop.clock.tick(frame, paused_, warming_up_ && warming_up_());
    if (loop.pass_timed_frames > 0 && frame == loop.frame_limit - loop.pass_timed_frames) {
        glFinish();  // the frames before it have finished: the clock's end
        loop.clock.stop(frame);
        timers_.set_enabled(true);
    }
    if (frame > 0) time_ += tick.dt;
    if (tick.wall - last_reload_check_ > 0.5) {
        last_reload_check_ = tick.wall;
        programs_.reload_changed();
    }
    this->frame(loop.probes, frame, tick.dt, tick.real_dt);
    const bool last = loop.frame_limit > 0 && frame + 1 == loop.frame_limit;
    if (!loop.options.record_dir.empty()) record_frame(loop.options.record_dir, frame);
    if (last && (!loop.options.screenshot.empty() || loop.headless))
        loop.screenshot = capture_frame(*context_, framebuffer_size_);
    context_->swap_buffers();
    timers_.collect();
    loop.probes.after_frame(frame);
    programs_.set_running();  // a variant that fails to build from now on is shown, not fatal
    ++loop.frame;
    return true;
}

int App::finish_loop() {
    FrameLoop& loop = *loop_;
    // Closed before the last frame: a headless target still holds the last picture.
    if (loop.closed_early && loop.headless && loop.frame > 0 && !loop.options.screenshot.empty())
        loop.screenshot = capture_frame(*context_, framebuffer_size_);
    write_outputs(loop.options, loop.screenshot, loop.clock, loop.frame);

    const GlDebugStats& gl = gl_debug_stats();
    if (gl.errors > 0 && loop.headless) {
        std::cerr << "error: " << gl.errors << " OpenGL error(s) in a headless run; first: "
                  << gl.first_error << std::endl;
        return kExitGlError;
    }
    return kExitOk;
}

#if defined(__EMSCRIPTEN__)
// One frame of a page; after the last, what main would do after run(): the exit status, the
// neighbouring chapter's page if one was chosen, and the exit the page reports (onExit).
void App::browser_frame(void* self) {
    App& app = *static_cast<App*>(self);
    int status = kExitOk;
    try {
        if (app.loop_turn()) return;
        status = app.finish_loop();
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << std::endl;
        status = kExitRuntimeError;
    }
    emscripten_cancel_main_loop();
    std::exit(run_next_step(status, app.next_step_command()));
}
#endif

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

    const bool drawable = framebuffer_size_.x > 0 && framebuffer_size_.y > 0;  // zero while minimised
    const bool split = drawable && split_view_ && split_variants_;
    const SplitVariants variants = split ? split_variants_() : SplitVariants{};
    const bool update_each_side = split && variants.update_each_side;
    if (!update_each_side) update(time_, dt);
    if (drawable) {
        const auto render_frame = [this, update_each_side, dt] {
            if (update_each_side) update(time_, dt);  // with this side's parameters
            bind_target();
            render();
        };
        if (split) {
            if (auto error = split_.render(params_, variants, framebuffer_size_,
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
