#include "common/app.hpp"

#include "common/error.hpp"
#include "common/gl_debug.hpp"
#include "common/image.hpp"
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

namespace {
std::vector<std::string> list_steps() {
    std::vector<std::string> steps;
    for (const auto& entry : fs::directory_iterator(OCEAN_SOURCE_DIR)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && name.size() > 7 && name.rfind("step", 0) == 0 && std::isdigit(name[4]) &&
            std::isdigit(name[5]) && name[6] == '_')
            steps.push_back(name);
    }
    std::sort(steps.begin(), steps.end());
    return steps;
}
}  // namespace

namespace {
// Ctrl-C (SIGINT) and SIGTERM close the step like its window's close button: the frame ends, the
// GL objects are released, the exit status is 0. A signal handler may only set a flag like this.
volatile std::sig_atomic_t g_close_requested = 0;
extern "C" void request_close_on_signal(int) { g_close_requested = 1; }
}  // namespace

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
        std::cout << usage_text(step_name(), info_.title + " (seed " + info_.seed_sections + ")");
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
    if (!options.export_dir.empty() && !supports_export())
        return fail(kExitUsage, "--export: " + step_name() + " has no maps to export (step05_fft and "
                                "step06_foam_sky have)");
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

void App::use_camera(glm::vec3 target, float distance, float yaw_deg, float pitch_deg) {
    camera_.declare_params(params_, target, distance, yaw_deg, pitch_deg);
    camera_enabled_ = true;
}

std::vector<std::string> App::stage_paths(const std::vector<std::string>& stage_files) const {
    // "dir/file" is relative to the repository (a later chapter using an earlier one's shader);
    // a bare name is the step's own, or else common/shaders' (fullscreen.vert, for one).
    std::vector<std::string> paths;
    for (const auto& file : stage_files) {
        if (file.find('/') != std::string::npos) {
            paths.push_back((fs::path(OCEAN_SOURCE_DIR) / file).string());
            continue;
        }
        const fs::path own = fs::path(shader_dir_) / file;
        const fs::path shared = fs::path(OCEAN_SOURCE_DIR) / "common" / "shaders" / file;
        paths.push_back((fs::exists(own) || !fs::exists(shared) ? own : shared).string());
    }
    return paths;
}

ShaderProgram& App::load_program(const std::string& name, const std::vector<std::string>& stage_files) {
    auto program = std::make_unique<ShaderProgram>(name, stage_paths(stage_files));
    if (auto error = program->build())
        throw Error("shader program '" + name + "' does not build: " + first_line_summary(*error));
    programs_.push_back(std::move(program));
    return *programs_.back();
}

ShaderProgram* App::program_variant(const std::string& name, const std::vector<std::string>& stage_files,
                                    const std::vector<std::string>& defines) {
    const std::string key = name + "|" + join(defines, "|");
    if (auto it = variants_.find(key); it != variants_.end()) return it->second;
    const std::string label = defines.empty() ? name : name + " [" + join(defines, ", ") + "]";
    auto program = std::make_unique<ShaderProgram>(label, stage_paths(stage_files), std::vector<std::string>{},
                                                   defines);
    if (auto error = program->build()) {
        if (!running_) throw Error("shader program '" + label + "' does not build: " + first_line_summary(*error));
        std::cerr << "shader program '" << label << "' does not build:\n" << *error;
        panel_message_ = "'" + label + "' does not build (previous program kept):\n" + *error;
        return nullptr;
    }
    programs_.push_back(std::move(program));
    return variants_[key] = programs_.back().get();
}

void App::reload_changed_shaders() {
    for (auto& program : programs_) {
        if (!program->sources_changed()) continue;
        if (auto error = program->build()) {
            std::cerr << "shader reload failed, keeping the last good '" << program->name()
                      << "':\n" << *error;
            panel_message_ = "reload failed (last good program kept):\n" + *error;
        } else {
            std::cerr << "shader '" << program->name() << "' reloaded\n";
            panel_message_.clear();
        }
    }
}

int App::run_loop(const Options& options) {
    const bool headless = options.headless || !display_available();
    if (!options.headless && headless) std::cout << "no display: rendering headless\n";
    shader_dir_ = options.shader_dir.empty() ? where_.dir + "/shaders" : options.shader_dir;
    if (!fs::is_directory(shader_dir_)) throw Error("shader directory '" + shader_dir_ + "' does not exist");

    context_ = Context::create({headless, options.width, options.height, step_name()});
    enable_gl_debug_output();
    std::cout << step_name() << ": " << context_->description() << "\n";
    empty_vao_ = make_vertex_array();
    all_steps_ = list_steps();
    timers_.set_enabled(options.bench);
    framebuffer_size_ = context_->framebuffer_size();
    init_imgui();
    init();

    const int frame_limit = options.frames > 0 ? options.frames : (headless ? 10 : 0);
    const bool fixed_clock = options.start_time.has_value() || options.fixed_dt.has_value();
    const double fixed_dt = options.fixed_dt.value_or(0.0);
    time_ = options.start_time.value_or(options.start_at.value_or(0.0));
    panel_visible_ = !headless || options.show_ui;

    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    auto previous = start;
    auto bench_start = start;
    Image screenshot;
    int frame = 0;
    g_close_requested = 0;
    std::signal(SIGINT, request_close_on_signal);
    std::signal(SIGTERM, request_close_on_signal);
    bool closed_early = false;
    for (; frame_limit == 0 || frame < frame_limit; ++frame) {
        context_->poll_events();
        if (context_->should_close() || g_close_requested) {
            closed_early = true;
            break;
        }
        const auto now = clock::now();
        const double real_dt = std::chrono::duration<double>(now - previous).count();
        const double wall = std::chrono::duration<double>(now - start).count();
        previous = now;
        if (frame == 1) bench_start = now;  // the first frame pays for compilation and uploads
        const double dt = paused_ ? 0.0 : (fixed_clock ? fixed_dt : real_dt);
        if (frame > 0) time_ += dt;

        if (wall - last_reload_check_ > 0.5) {
            last_reload_check_ = wall;
            reload_changed_shaders();
        }
        framebuffer_size_ = context_->framebuffer_size();
        if (options.exercise_minimise && (frame == 2 || frame == 3)) {
            framebuffer_size_ = glm::ivec2(0);  // as a minimised window reports
            if (GLFWwindow* window = context_->window(); window != nullptr && frame == 2) glfwIconifyWindow(window);
            if (GLFWwindow* window = context_->window(); window != nullptr && frame == 3) glfwRestoreWindow(window);
        }
        if (camera_enabled_) camera_.apply(read_camera_input(), float(real_dt));

        ImGui_ImplOpenGL3_NewFrame();
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
            if (split_view_ && split_variants())
                render_split(*split_variants());
            else {
                bind_target();
                render();
            }
            if (panel_visible_) {
                bind_target();
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            }
        }
        check_gl_errors("the frame");
        const bool last = frame_limit > 0 && frame + 1 == frame_limit;
        if (last && (!options.screenshot.empty() || headless))
            screenshot = read_framebuffer(context_->target_framebuffer(), framebuffer_size_.x,
                                          framebuffer_size_.y);
        context_->swap_buffers();
        timers_.collect();
        if (options.resource_log > 0 && (frame + 1) % options.resource_log == 0)
            std::cout << "resources: frame " << frame + 1 << " rss_kb " << resident_kilobytes() << " gl_objects "
                      << live_gl_objects() << std::endl;
        running_ = true;  // a variant that fails to build from now on is shown, not fatal
    }
    const double bench_seconds = std::chrono::duration<double>(clock::now() - bench_start).count();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    // Closed before the last frame: a headless target still holds the last picture.
    if (closed_early && headless && frame > 0 && !options.screenshot.empty() && framebuffer_size_.x > 0)
        screenshot = read_framebuffer(context_->target_framebuffer(), framebuffer_size_.x, framebuffer_size_.y);

    if (!screenshot.rgba.empty()) {
        const std::string path = options.screenshot.empty() ? "screenshots/" + step_name() + ".png"
                                                            : options.screenshot;
        const fs::path parent = fs::path(path).parent_path();
        std::error_code ec;
        if (!parent.empty()) fs::create_directories(parent, ec);
        if (auto error = save_png(screenshot, path)) throw Error(*error);
        std::cout << "screenshot: " << fs::absolute(path).string() << "\n";
    }
    if (!options.export_dir.empty()) {
        std::error_code ec;
        fs::create_directories(options.export_dir, ec);
        if (ec) throw Error("--export: cannot create '" + options.export_dir + "': " + ec.message());
        export_results(options.export_dir);
        std::cout << "export: " << fs::absolute(options.export_dir).string() << "\n";
    }
    if (options.bench) {
        std::cout << timers_.report(bench_seconds, std::max(0, frame - 1));
        bench_extra(std::cout);
    }

    const GlDebugStats& gl = gl_debug_stats();
    if (gl.errors > 0 && headless) {
        std::cerr << "error: " << gl.errors << " OpenGL error(s) in a headless run; first: "
                  << gl.first_error << std::endl;
        return kExitGlError;
    }
    return kExitOk;
}

void App::render_split(const SplitVariants& variants) {
    // Render the whole frame once per variant (the steps' own passes stay untouched), keep the
    // left half of the first, and put it over the second. Parameters are restored afterwards.
    const std::string saved = params_.preset_text("split view");
    const glm::ivec2 size = framebuffer_size_;
    if (split_size_ != size) {
        split_colour_ = make_renderbuffer();
        glNamedRenderbufferStorage(split_colour_.id(), GL_RGBA8, size.x, size.y);
        split_target_ = make_framebuffer();
        glNamedFramebufferRenderbuffer(split_target_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, split_colour_.id());
        split_size_ = size;
    }
    const int middle = size.x / 2;
    for (int side = 0; side < 2; ++side) {
        for (const auto& assignment : side == 0 ? variants.left : variants.right)
            if (auto error = params_.set_assignment(assignment)) panel_message_ = "split view: " + *error;
        split_side_ = side;
        bind_target();
        render();
        const GLuint target = context_->target_framebuffer();
        if (side == 0)
            glBlitNamedFramebuffer(target, split_target_.id(), 0, 0, middle, size.y, 0, 0, middle, size.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
        else
            glBlitNamedFramebuffer(split_target_.id(), target, 0, 0, middle, size.y, 0, 0, middle, size.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
        params_.apply_preset_text(saved, "split view");
    }
    split_side_ = -1;
    // A thin white line between the halves.
    bind_target();
    glEnable(GL_SCISSOR_TEST);
    glScissor(middle - 1, 0, 2, size.y);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}


std::string App::step_executable(const std::string& step) const {
    // Steps are built side by side: build/<preset>/<step>/<step>.
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return "";
    const fs::path candidate = self.parent_path().parent_path() / step / step;
    return fs::exists(candidate) ? candidate.string() : "";
}

void App::hand_over_to(const std::string& step) {
    const std::string executable = step_executable(step);
    if (executable.empty()) {
        panel_message_ = step + " is not built next to this step";
        return;
    }
    // The same moment and the same view: the camera carries over between 3D steps.
    handoff_ = {executable, "--start-at", std::to_string(time_), "--size",
                std::to_string(framebuffer_size_.x) + "x" + std::to_string(framebuffer_size_.y)};
    if (camera_enabled_ && step.substr(0, 6) != "step01")
        for (const char* name : {"camera_mode", "camera_yaw", "camera_pitch", "camera_distance", "camera_target_x",
                                 "camera_target_y", "camera_target_z", "camera_fov"})
            if (const Param* p = params_.find(name)) {
                handoff_.push_back("--set");
                handoff_.push_back(std::string(name) + "=" + p->value_text());
            }
    if (split_view_) handoff_.push_back("--split");
    context_->request_close();
}

long resident_kilobytes() {
    // /proc/self/statm: size, resident, ... in pages.
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

int hand_off(int status, const std::vector<std::string>& command) {
    if (command.empty()) return status;
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::cerr << "error: cannot start " << command[0] << ": " << std::strerror(errno) << std::endl;
    return kExitRuntimeError;
}

void App::on_scroll(GLFWwindow* window, double /*dx*/, double dy) {
    auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (app != nullptr && !ImGui::GetIO().WantCaptureMouse) app->scroll_accumulated_ += float(dy);
}

void App::init_imgui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini files left in the working directory
    ImGui::StyleColorsDark();
    if (GLFWwindow* window = context_->window()) {
        glfwSetWindowUserPointer(window, this);
        glfwSetScrollCallback(window, &App::on_scroll);  // before ImGui, which chains to it
        ImGui_ImplGlfw_InitForOpenGL(window, true);
    }
    if (!ImGui_ImplOpenGL3_Init("#version 450 core"))
        throw Error("ImGui's OpenGL 3 backend cannot start on this context");
    imgui_ready_ = true;
}

void App::shutdown_imgui() {
    if (!imgui_ready_) return;
    ImGui_ImplOpenGL3_Shutdown();
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
