// The base class of every step. A step declares its parameters in its constructor, then
// overrides a few hooks; the framework owns the context, the run loop, the clock, input, the
// ImGui panel, shaders, screenshots and benchmarks.
//
//   class Step02 : public ocean::App {
//       Step02() : App({"Sum of sines in 3D", "1.2.2", "..."}) { params().add_float(...); }
//       void init() override;                        // GL resources, programs
//       void update(double time, double dt) override; // simulation
//       void render() override;                      // draw into the bound target
//       void ui() override;                          // extra panel widgets (optional)
//   };
//   OCEAN_MAIN(Step02)
#pragma once

#include "common/camera.hpp"
#include "common/cli.hpp"
#include "common/context.hpp"
#include "common/gpu_timer.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"

#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ocean {

struct StepInfo {
    std::string title;          // "Sum of sines in 3D"
    std::string seed_sections;  // "1.2.2"
    std::string description;    // a paragraph: what the step shows and what is new
};

struct StepLocation {
    std::string name;  // "step02_sine3d": folder, target and window title
    std::string dir;   // the step's source folder, where shaders/ lives
};

// Exit statuses, the same for every step (README: "Exit status").
enum ExitCode { kExitOk = 0, kExitRuntimeError = 1, kExitUsage = 2, kExitGlError = 3 };

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
    const std::vector<std::string>& handoff() const { return handoff_; }

protected:
    virtual void init() {}
    virtual void update(double /*time*/, double /*dt*/) {}
    virtual void render() = 0;
    virtual void ui() {}
    // Steps that simulate maps write them for --export (after the last frame); throw ocean::Error
    // on failure.
    virtual bool supports_export() const { return false; }
    virtual void export_results(const std::string& /*dir*/) {}
    // More --bench lines after the per-pass table (step05 compares its FFT backends).
    virtual void bench_extra(std::ostream& /*out*/) {}

    // The split view (--split, or the panel): the chapter's two main variants, each a list of
    // parameter assignments, drawn left and right of the screen's middle. Steps without one
    // return nothing.
    struct SplitVariants {
        std::string left_label, right_label;
        std::vector<std::string> left, right;  // "name=value" each
    };
    virtual std::optional<SplitVariants> split_variants() const { return std::nullopt; }
    // Every step of the repository, in order (the folders step01_* ... of the source tree).
    const std::vector<std::string>& all_steps() const { return all_steps_; }
    // Ends this step after the frame and starts `step` at the same time, size, camera and split
    // (the panel's Previous/Next buttons).
    void hand_over_to(const std::string& step);

    // While a split frame renders: 0 for the left variant, 1 for the right, -1 otherwise. A step
    // advances its simulation state (foam, say) only once a frame: when split_side() < 1.
    int split_side() const { return split_side_; }

    ParamRegistry& params() { return params_; }
    // Loads a program from files in the step's shaders/ folder (or --shader-dir); throws
    // ocean::Error at start-up if it does not build. It then hot-reloads on its own.
    ShaderProgram& load_program(const std::string& name, const std::vector<std::string>& stage_files);
    // A compile-time variant of a program (`defines` such as "VIEW 3"), built on first use and
    // kept. Before the first frame a failure throws like load_program; later (the user switched
    // to a variant after breaking a shader) it returns nullptr and shows the error in the panel,
    // and the step keeps drawing with the program it had.
    ShaderProgram* program_variant(const std::string& name, const std::vector<std::string>& stage_files,
                                   const std::vector<std::string>& defines);
    // program_variant as a ProgramFactory, for a technique's classes (GpuOcean, Sky, ...).
    ProgramFactory program_factory() {
        return [this](const std::string& name, const std::vector<std::string>& files,
                      const std::vector<std::string>& defines) { return program_variant(name, files, defines); };
    }
    // Declares the camera_* parameters and turns on mouse/keyboard camera control.
    void use_camera(glm::vec3 target, float distance, float yaw_deg, float pitch_deg);
    Camera& camera() { return camera_; }
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
    int run_loop(const Options& options);
    void init_imgui();
    void shutdown_imgui();
    void reload_changed_shaders();
    std::vector<std::string> stage_paths(const std::vector<std::string>& stage_files) const;
    void draw_panel(float frame_ms);
    void render_split(const SplitVariants& variants);
    std::string step_executable(const std::string& step) const;
    CameraInput read_camera_input();
    static void on_scroll(struct GLFWwindow* window, double dx, double dy);

    StepInfo info_;
    StepLocation where_;
    ParamRegistry params_;
    Camera camera_;
    bool camera_enabled_ = false;
    // Declared before every GL object below so that it is destroyed after them.
    std::unique_ptr<Context> context_;
    std::vector<std::unique_ptr<ShaderProgram>> programs_;
    std::map<std::string, ShaderProgram*> variants_;  // name + defines -> one of programs_
    bool running_ = false;  // past init(): build failures no longer end the program
    std::string shader_dir_;
    GpuTimers timers_;
    VertexArray empty_vao_;
    glm::ivec2 framebuffer_size_{0};
    double time_ = 0;
    bool paused_ = false;
    bool panel_visible_ = true;
    bool imgui_ready_ = false;
    float scroll_accumulated_ = 0;
    glm::dvec2 last_mouse_{0.0};
    std::string preset_path_ = "preset.txt";
    std::string panel_message_;
    double last_reload_check_ = 0;
    bool split_view_ = false;
    std::vector<std::string> handoff_;
    std::vector<std::string> all_steps_;
    int split_side_ = -1;
    Renderbuffer split_colour_;
    Framebuffer split_target_;
    glm::ivec2 split_size_{0};
};

// Resident memory of this process, kB (the soak test's sample).
long resident_kilobytes();

// Replaces this process with `command` (Prev/Next) once the step is gone, or returns status.
int hand_off(int status, const std::vector<std::string>& command);

}  // namespace ocean

#define OCEAN_MAIN(StepClass)                                                   \
    int main(int argc, char** argv) {                                           \
        std::vector<std::string> next;                                          \
        int status = 0;                                                         \
        {                                                                       \
            StepClass app;                                                      \
            status = app.run(argc, argv, {OCEAN_STEP_NAME, OCEAN_STEP_DIR});     \
            next = app.handoff();                                               \
        }                                                                       \
        return ocean::hand_off(status, next);                                   \
    }
