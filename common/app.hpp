// The base class of every step. A step declares its parameters (and the services it offers) in
// its constructor, then writes four hooks; the framework owns the context, the run loop, the
// clock, input, the ImGui panel, shaders, screenshots and benchmarks.
//
//   class Chapter : public ocean::App {
//       Chapter() : App({"Sum of sines in 3D", "1.2.2", "..."}) { params().add_float(...); }
//       void init() override;                        // GL resources, programs
//       void update(double time, double dt) override; // simulation
//       void render() override;                      // draw into the bound target
//       void ui() override;                          // extra panel widgets (optional)
//   };
//   OCEAN_MAIN(Chapter)
//
// One frame, in this order (App::frame in app.cpp):
//   1. input: the window's events since the last frame, each press in order (F1, Esc, F5, C act
//      here, input_events.hpp); the camera moves (mouse, keys); frame_input() holds the rest;
//   2. update(time, dt): once, GPU passes included (once per side with a split view whose
//      variants change what it computes: SplitVariants::update_each_side);
//   3. render(): into the target; twice with the split view, once per variant (split_view.hpp);
//   4. the panel: the framework's widgets, then ui(), showing this frame's state; what the user
//      changes there takes effect from the next frame's update();
//   5. present, then the test probes (run_support.hpp).
// Services a step opts into from its constructor: offer_split_view, offer_export,
// offer_bench_figures.
#pragma once

#include "common/camera.hpp"
#include "common/cli.hpp"
#include "common/context.hpp"
#include "common/gpu_timer.hpp"
#include "common/grid.hpp"
#include "common/hand_over.hpp"
#include "common/input_events.hpp"
#include "common/params.hpp"
#include "common/program_library.hpp"
#include "common/shader.hpp"
#include "common/split_view.hpp"

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ocean {

class PanelState;  // panel_state.hpp
class PanelFit;

struct StepInfo {
    std::string title;          // "Sum of sines in 3D"
    std::string notes_sections;  // "1.2.2"; empty for a chapter beyond the notes
    std::string description;    // a paragraph: what the step shows and what is new
    // Multisampling of the window (a headless run has none): 4 smooths the edges of a mesh drawn
    // straight into it; 0 for a step that draws its scene off-screen and sends it to the window in
    // one full-screen pass, where the samples would only cost.
    int window_samples = 4;
    // "notes 1.2.2", or "beyond the notes" (--help's first line, the panel, the contact sheet).
    std::string notes_label() const { return notes_sections.empty() ? "beyond the notes" : "notes " + notes_sections; }
};

struct StepLocation {
    std::string name;  // the step's folder, target and window title
    std::string dir;   // the step's source folder, where shaders/ lives
};


class App {
public:
    explicit App(StepInfo info);
    virtual ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // `where` names the step's folder and target (OCEAN_MAIN passes what CMake fixed).
    int run(int argc, char** argv, const StepLocation& where);
    int run(const std::vector<std::string>& args, const StepLocation& where);

    const StepInfo& info() const { return info_; }
    const std::string& step_name() const { return where_.name; }
    // The command that starts the neighbouring step the user chose (Prev/Next), or nothing.
    const std::vector<std::string>& next_step_command() const { return next_step_command_; }

protected:
    // The four hooks, in the order each frame runs them (see the top of this file).
    virtual void init() {}
    // Once a frame, before the frame's render(s): advance the simulation, GPU passes included.
    virtual void update(double /*time*/, double /*dt*/) {}
    // Draws the frame into the bound target. With the split view it runs twice a frame (see
    // split_view.hpp), so per-frame state belongs in update().
    virtual void render() = 0;
    // The step's own panel widgets, after the framework's, once the frame is drawn.
    virtual void ui() {}

    // Services, offered from the constructor (the command line is checked against them before the
    // first frame):
    // The split view (--split, or the panel): `variants` gives its two variants as parameter
    // assignments, drawn left and right of the screen's middle (split_view.hpp).
    using SplitVariants = ocean::SplitVariants;
    void offer_split_view(std::function<SplitVariants()> variants) { split_variants_ = std::move(variants); }
    // --export DIR: `write` saves the step's simulated maps into DIR after the last frame (throws
    // ocean::Error on failure).
    void offer_export(std::function<void(const std::string& dir)> write) { export_ = std::move(write); }
    // --bench: `measure` runs after the per-pass table and returns extra figures as (label,
    // milliseconds), printed and carried in the machine-readable line (a step's FFT backends).
    using BenchFigures = std::vector<std::pair<std::string, double>>;
    void offer_bench_figures(std::function<BenchFigures()> measure) { bench_figures_ = std::move(measure); }
    // --bench times the steady state: while `warming_up` says so (a backend still being chosen on
    // the frames themselves), its frames-per-second clock waits (run_support.hpp's FrameClock).
    void offer_warm_up(std::function<bool()> warming_up) { warming_up_ = std::move(warming_up); }
    // A line for the panel (a preset saved, a step that is not built): shown until the next one.
    void show_message(std::string message) { panel_message_ = std::move(message); }
    // Every step of the repository, in order (CMake's list of stepNN_* folders).
    const std::vector<std::string>& all_steps() const { return all_steps_; }
    // Ends this step after the frame and starts `step` at the same time, size, camera, split and
    // pause (the panel's Previous/Next buttons).
    void hand_over_to(const std::string& step);

    ParamRegistry& params() { return params_; }
    // The one way to get a shader program: built on first use from the step's shaders/ (or
    // --shader-dir, common/shaders, or "stepNN_x/shaders/file" of an earlier chapter), kept, and
    // hot-reloaded (program_library.hpp). `defines` select a compile-time variant. A program that
    // does not build stops the step at start-up; later, the last good program of that name is
    // returned (nullptr only if there never was one) and the error shows in the panel.
    ShaderProgram* program(const std::string& name, const std::vector<std::string>& stage_files,
                           const std::vector<std::string>& defines = {}) {
        return programs_.get(name, stage_files, defines);
    }
    // A chapter built on an earlier chapter's program (step07 on step06's): bare shader names its
    // own folder lacks are read from `step`'s shaders (call from the constructor).
    void use_shaders_of(const std::string& step) { programs_.inherit_shaders_of(step + "/shaders"); }
    // The same, for a chapter's technique classes (OceanSimulation, Sky, ...).
    ProgramFactory program_factory() { return programs_.factory(); }
    // Declares the camera_* parameters and turns on mouse/keyboard camera control.
    void use_camera(const CameraView& view, double reach = kNearReach);
    Camera& camera() { return camera_; }
    // This frame's mouse, for a step's own controls (step01 pans its plot, step07 pushes a body),
    // read in update() or ui(); empty when headless. The camera, where a step uses one, has
    // already moved with `drag` and `scroll`.
    struct FrameInput {
        std::vector<InputEvent> presses;  // the mouse-button presses ImGui did not take, in order
        glm::vec2 drag{0.0f};             // pixels moved with the left button down (not on the panel)
        float scroll = 0;                 // wheel steps (not over the panel)
        glm::dvec2 cursor{0.0};           // the cursor now, window pixels from the top left
        bool drag_ended = false;          // the left button came up this frame, ending a drag
    };
    const FrameInput& frame_input() const { return frame_input_; }
    GpuTimers& timers() { return timers_; }

    glm::ivec2 framebuffer_size() const { return framebuffer_size_; }
    float aspect() const;
    double time() const { return time_; }
    bool headless() const;
    // Binds the output framebuffer (window or offscreen) with a full viewport.
    void bind_target() const;
    // Clears the bound target to `colour` (sRGB as stored) and the depth buffer to far.
    void clear_target(glm::vec3 colour) const;
    // One triangle that covers the screen; pair with common/shaders/fullscreen.vert.
    void draw_fullscreen_triangle() const;
    GLuint fullscreen_vao() const { return empty_vao_.id(); }  // for passes that draw it themselves

private:
    // The frame loop: run_loop sets it up and runs loop_turn until it says the run is over (a page
    // has the browser call browser_frame instead), then finish_loop writes the outputs.
    struct FrameLoop;
    int run_loop(const Options& options);
    bool loop_turn();
    int finish_loop();
    static void browser_frame(void* self);
    void frame(const class TestProbes& probes, int frame, double dt, double real_dt);
    // Output writing (app_output.cpp): --record, the screenshot, --export, --bench (what `clock`
    // timed of the run's `frames`).
    void write_outputs(const Options& options, const struct Image& screenshot, const class FrameClock& clock,
                       int frames);
    void record_frame(const std::string& dir, int frame);
    // The ImGui layer (imgui_layer.cpp) and the panel (panel.cpp).
    void init_imgui(bool draw_panel);
    void begin_imgui_frame(double dt);
    void end_imgui_frame();
    void shutdown_imgui();
    void draw_panel(float frame_ms);
    // Window input (app_input.cpp): the GLFW callbacks queue the events (installed before
    // ImGui's, which chain to them); read_input takes them once a frame, after ImGui's NewFrame.
    void read_input();
    void act_on_key(KeyAction action);
    void report_camera() const;  // after a drag: the view as --set flags
    CameraInput read_camera_input() const;
    static void on_scroll(struct GLFWwindow* window, double dx, double dy);
    static void on_cursor_pos(struct GLFWwindow* window, double x, double y);
    static void on_key(struct GLFWwindow* window, int key, int scancode, int action, int mods);
    static void on_mouse_button(struct GLFWwindow* window, int button, int action, int mods);

    StepInfo info_;
    StepLocation where_;
    ParamRegistry params_;
    Camera camera_;
    bool camera_enabled_ = false;
    // Declared before every GL object below so that it is destroyed after them.
    std::unique_ptr<Context> context_;
    ProgramLibrary programs_;
    GpuTimers timers_;
    VertexArray empty_vao_;
    glm::ivec2 framebuffer_size_{0};
    double time_ = 0;
    bool paused_ = false;
    bool panel_visible_ = true;
    std::unique_ptr<PanelState> panel_state_;  // windowed runs only: headless pictures stay reproducible
    std::unique_ptr<PanelFit> panel_fit_;      // the panel's size, frame by frame
    bool panel_overflow_reported_ = false;    // panel.cpp's check, once a run
    bool imgui_ready_ = false;
    bool imgui_renderer_ready_ = false;  // ImGui's OpenGL 3 backend, only where the panel is drawn
    float scroll_accumulated_ = 0;
    InputQueue input_queue_;  // filled by the callbacks between frames
    DragTracker drag_;
    glm::dvec2 cursor_{0.0};  // where the events being delivered happened (on_cursor_pos)
    FrameInput frame_input_;
    std::string preset_path_ = "preset.txt";
    double last_reload_check_ = 0;
    bool split_view_ = false;
    SplitView split_;
    std::function<SplitVariants()> split_variants_;
    std::function<void(const std::string&)> export_;
    std::function<BenchFigures()> bench_figures_;
    std::function<bool()> warming_up_;
    std::string panel_message_;
    std::vector<std::string> next_step_command_;
    std::vector<std::string> all_steps_;
    std::unique_ptr<FrameLoop> loop_;
};

}  // namespace ocean

#define OCEAN_MAIN(StepClass)                                                   \
    int main(int argc, char** argv) {                                           \
        std::vector<std::string> next;                                          \
        int status = 0;                                                         \
        {                                                                       \
            StepClass app;                                                      \
            status = app.run(argc, argv, {OCEAN_STEP_NAME, OCEAN_STEP_DIR});     \
            next = app.next_step_command();                                               \
        }                                                                       \
        return ocean::run_next_step(status, next);                                   \
    }
