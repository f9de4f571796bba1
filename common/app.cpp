#include "common/app.hpp"

#include "common/error.hpp"
#include "common/gl_debug.hpp"
#include "common/image.hpp"
#include "common/run_support.hpp"
#include "common/text.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
        std::cout << usage_text(step_name(), info_.title + " (notes " + info_.notes_sections + ")");
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
    if (!options.export_dir.empty() && !supports_export())
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

void App::use_camera(const CameraView& view) {
    camera_.declare_params(params_, view);
    camera_enabled_ = true;
}

void App::draw_grid(const ShaderProgram& program, const GridMesh& grid, bool wireframe, float cull_margin) {
    const glm::mat4 view_projection = camera_.projection(aspect()) * camera_.view();
    program.set("u_view_projection", view_projection);
    program.set("u_eye", camera_.eye());
    GpuScope timed(timers_, "ocean");
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program.id());
    if (cull_margin >= 0)
        grid.draw_visible(view_projection, cull_margin, wireframe);
    else
        grid.draw(wireframe);
    glDisable(GL_DEPTH_TEST);
}

int App::run_loop(const Options& options) {
    const bool headless = options.headless || !display_available();
    if (!options.headless && headless) std::cout << "no display: rendering headless\n";
    const std::string shader_dir = options.shader_dir.empty() ? where_.dir + "/shaders" : options.shader_dir;
    if (!fs::is_directory(shader_dir)) throw Error("shader directory '" + shader_dir + "' does not exist");
    programs_.set_shader_dir(where_.dir + "/shaders", shader_dir);

    context_ = Context::create({headless, options.width, options.height, step_name()});
    enable_gl_debug_output();
    std::cout << step_name() << ": " << context_->description() << "\n";
    empty_vao_ = make_vertex_array();
    all_steps_ = repository_steps();
    timers_.set_enabled(options.bench);
    framebuffer_size_ = context_->framebuffer_size();
    panel_visible_ = !headless || options.show_ui;
    init_imgui(panel_visible_);
    init();

    const int frame_limit = options.frames > 0 ? options.frames : (headless ? 10 : 0);
    FrameClock clock(options);
    time_ = clock.start_time();
    Image screenshot;
    int frame = 0;
    CloseOnSignal signals;
    bool closed_early = false;
    for (; frame_limit == 0 || frame < frame_limit; ++frame) {
        context_->poll_events();
        if (context_->should_close() || signals.requested()) {
            closed_early = true;
            break;
        }
        const FrameClock::Tick tick = clock.tick(frame, paused_);
        if (frame > 0) time_ += tick.dt;
        if (tick.wall - last_reload_check_ > 0.5) {
            last_reload_check_ = tick.wall;
            programs_.reload_changed();
        }
        this->frame(options, frame, tick.dt, tick.real_dt);
        const bool last = frame_limit > 0 && frame + 1 == frame_limit;
        if (!options.record_dir.empty()) record_frame(options.record_dir, frame);
        if (last && (!options.screenshot.empty() || headless)) screenshot = capture_frame(*context_, framebuffer_size_);
        context_->swap_buffers();
        timers_.collect();
        if (options.resource_log > 0 && (frame + 1) % options.resource_log == 0)
            std::cout << "resources: frame " << frame + 1 << " rss_kb " << resident_kilobytes() << " gl_objects "
                      << live_gl_objects() << std::endl;
        programs_.set_running();  // a variant that fails to build from now on is shown, not fatal
    }
    // Closed before the last frame: a headless target still holds the last picture.
    if (closed_early && headless && frame > 0 && !options.screenshot.empty())
        screenshot = capture_frame(*context_, framebuffer_size_);
    write_outputs(options, screenshot, frame, clock.bench_seconds());

    const GlDebugStats& gl = gl_debug_stats();
    if (gl.errors > 0 && headless) {
        std::cerr << "error: " << gl.errors << " OpenGL error(s) in a headless run; first: "
                  << gl.first_error << std::endl;
        return kExitGlError;
    }
    return kExitOk;
}

void App::frame(const Options& options, int frame, double dt, double real_dt) {
    framebuffer_size_ = context_->framebuffer_size();
    if (options.exercise_minimise) framebuffer_size_ = exercise_minimise(*context_, frame, framebuffer_size_);
    if (camera_enabled_) camera_.apply(read_camera_input(), float(real_dt));

    if (imgui_renderer_ready_) ImGui_ImplOpenGL3_NewFrame();
    if (context_->window() != nullptr) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        ImGui::GetIO().DisplaySize = ImVec2(float(framebuffer_size_.x), float(framebuffer_size_.y));
        ImGui::GetIO().DeltaTime = float(dt > 0 ? dt : 1.0 / 60.0);
    }
    ImGui::NewFrame();
    draw_panel(float(real_dt * 1000.0));
    ImGui::Render();

    update(time_, dt);
    if (framebuffer_size_.x > 0 && framebuffer_size_.y > 0) {  // zero while minimised
        const auto render_frame = [this] {
            bind_target();
            render();
        };
        const auto variants = split_view_ ? split_variants() : std::nullopt;
        if (variants) {
            std::string message;
            split_.render(params_, *variants, framebuffer_size_, context_->target_framebuffer(), render_frame,
                          &message);
            if (!message.empty()) programs_.set_message(message);
        } else {
            render_frame();
        }
        if (panel_visible_ && imgui_renderer_ready_) {
            bind_target();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
    }
    check_gl_errors("the frame");
}

// --record: this frame as DIR/frame_NNNN.png (four digits, more past 9999), read before the
// buffers swap. The folder is created at the first frame.
void App::record_frame(const std::string& dir, int frame) {
    if (framebuffer_size_.x <= 0 || framebuffer_size_.y <= 0) return;  // minimised: nothing drawn
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    save_screenshot(capture_frame(*context_, framebuffer_size_), (fs::path(dir) / name).string());
}

void App::write_outputs(const Options& options, const Image& screenshot, int frames, double bench_seconds) {
    if (!screenshot.rgba.empty()) {
        const std::string path = options.screenshot.empty() ? "screenshots/" + step_name() + ".png" : options.screenshot;
        std::cout << "screenshot: " << save_screenshot(screenshot, path) << "\n";
    }
    if (!options.export_dir.empty()) {
        export_results(prepare_export_dir(options.export_dir));
        std::cout << "export: " << fs::absolute(options.export_dir).string() << "\n";
    }
    if (options.bench) {
        std::cout << timers_.report(bench_seconds, std::max(0, frames - 1));
        const auto extra = bench_extra();  // the step prints its own lines, then hands the figures
        std::cout << bench_csv_line(step_name(), framebuffer_size_, timers_, bench_seconds, std::max(0, frames - 1),
                                    extra);
    }
}

void App::hand_over_to(const std::string& step) {
    const std::string executable = step_executable(step);
    if (executable.empty()) {
        programs_.set_message(step + " is not built next to this step");
        return;
    }
    handoff_ = handoff_command(executable, time_, framebuffer_size_, params_, split_view_);
    context_->request_close();
}

long resident_kilobytes() {
    // /proc/self/statm: size, resident, ... in pages.
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

void App::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
    auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (app != nullptr && !ImGui::GetIO().WantCaptureMouse) app->scroll_accumulated_ += float(dy);
}

// ImGui frames run in every run (the keys F1, F5, Esc are read through them), but the panel is
// only drawn in a window or with --ui. ImGui's OpenGL 3 backend is started only then: in 1.86 it loads its GL
// functions through libGL.so.1 and GLX, which a GPU server rendering through EGL may not have.
void App::init_imgui(bool draw_panel) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini files left in the working directory
    ImGui::StyleColorsDark();
    imgui_ready_ = true;
    if (GLFWwindow* window = context_->window()) {
        glfwSetWindowUserPointer(window, this);
        glfwSetScrollCallback(window, &App::on_scroll);  // before ImGui, which chains to it
        ImGui_ImplGlfw_InitForOpenGL(window, true);
    }
    if (!draw_panel) {
        ImGui::GetIO().Fonts->Build();  // what the renderer's NewFrame would do; no texture needed
        return;
    }
    if (!ImGui_ImplOpenGL3_Init("#version 450 core"))
        throw Error("ImGui's OpenGL 3 backend cannot start: it loads GL through libGL.so.1 "
                    "(install libgl1), even when the context comes from EGL");
    imgui_renderer_ready_ = true;
}

void App::shutdown_imgui() {
    if (!imgui_ready_) return;
    if (imgui_renderer_ready_) ImGui_ImplOpenGL3_Shutdown();
    imgui_renderer_ready_ = false;
    if (context_ && context_->window() != nullptr) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    imgui_ready_ = false;
}

CameraInput App::read_camera_input() {
    CameraInput input;
    GLFWwindow* window = context_->window();
    if (window == nullptr) return input;
    const ImGuiIO& io = ImGui::GetIO();
    glm::dvec2 mouse;
    glfwGetCursorPos(window, &mouse.x, &mouse.y);
    if (!io.WantCaptureMouse && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
        input.drag = glm::vec2(mouse - last_mouse_);
    last_mouse_ = mouse;
    input.scroll = std::exchange(scroll_accumulated_, 0.0f);
    if (!io.WantCaptureKeyboard) {
        auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                      key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        input.fast = key(GLFW_KEY_LEFT_SHIFT) > 0;
    }
    if (input.drag != glm::vec2(0.0f) || input.scroll != 0.0f) params_.mark_changed();
    return input;
}

}  // namespace ocean
