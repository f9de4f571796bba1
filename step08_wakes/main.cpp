// step08_wakes: the waves a boat makes, seen from above.
// Beyond the notes. A wave field around the boat (wave_field.hpp: heights and a velocity potential,
// each Fourier mode turned by its own frequency omega = sqrt(g k tanh kh)) is pushed by the boat's
// hull, a patch of pressure sailing with it (wake_scene.hpp), and by stones dropped with a click;
// Kelvin's wake opens behind the boat at 19.5 degrees, narrower when it goes fast.
// Controls: the left and right arrows (held) turn the boat; a left click drops a stone; the panel
// sets the boat's speed, length and draft.
#include "common/app.hpp"
#include "common/error.hpp"
#include "common/gl_texture.hpp"
#include "step08_wakes/kelvin.hpp"
#include "step08_wakes/wake_experiments.hpp"
#include "step08_wakes/wake_scene.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

class Wakes : public ocean::App {
public:
    Wakes()
        : App({"Wakes", "-",
               "The waves a boat makes: a field of heights and potentials around it, each wave turned at its own "
               "frequency sqrt(g k tanh kh). The wake opens at Kelvin's 19.5 degrees; faster, it narrows. "
               "Arrows: turn the boat; left click: drop a stone."}) {
        ocean::ParamRegistry& p = params();
        p.add_float("boat_speed", &boat_.speed, 0, 12, "the boat's speed, metres per second");
        p.add_float("boat_length", &boat_.length, 1, 20, "the boat's length at the waterline, metres");
        p.add_float("draft", &boat_.draft, 0, 2, "how deep the hull presses the water at its middle, metres");
        p.add_float("rudder", &rudder_, -1, 1, "the rudder, -1 (port) to 1 (starboard); the arrows add to it");
        p.add_float("depth", &depth_, 0.5f, 1000, "the water's depth, metres (1000: deep)").logarithmic();
        p.add_choice("cells", &cells_choice_, {"64", "128", "256"}, "the wave field's cells a side");
        p.add_float("cell", &cell_, 0.1f, 2, "the wave field's cell, metres");
        p.add_float("warm_up", &warm_up_, 0, 120, "seconds the boat sails before the first frame");
        p.add_float("relief", &relief_, 1, 50, "how many times the shading exaggerates the slopes").logarithmic();
        p.add_bool("kelvin_lines", &kelvin_lines_, "draw Kelvin's edges, 19.47 degrees either side of the track");
        p.add_bool("show_field", &show_field_, "outline the field's grid and its absorbing layer");
        offer_bench_figures([this] { return time_the_field(); });
    }

private:
    step08::WaveFieldSettings field_settings() const {
        step08::WaveFieldSettings s;
        s.n = 64 << cells_choice_;
        s.cell = cell_;
        s.depth = depth_ >= 1000 ? std::numeric_limits<double>::infinity() : double(depth_);
        s.absorbing_width = 0.125 * s.n * s.cell;  // an eighth of the side at each edge
        return s;
    }

    void update(double, double dt) override {
        read_input();
        const step08::WaveFieldSettings wanted = field_settings();
        if (!scene_ || wanted.n != scene_->field().n() || wanted.cell != scene_->field().settings().cell ||
            wanted.depth != scene_->field().settings().depth) {
            scene_ = std::make_unique<step08::WakeScene>(wanted);
            scene_->sail(warm_up_, boat_, rudder_);  // the window opens on a wake already made
        }
        for (const glm::dvec2& stone : stones_) scene_->drop_stone(stone);
        stones_.clear();
        scene_->sail(dt, boat_, double(rudder_) + key_rudder_);
    }

    // --bench: the wave field runs on the CPU, outside the GPU passes the table times; here a copy
    // of the scene sails 15 frames of 1/60 s, each timed (median, milliseconds).
    BenchFigures time_the_field() const {
        if (!scene_) return {};
        step08::WakeScene scene = *scene_;
        std::vector<double> times;
        for (int i = 0; i < 15; ++i) {
            const auto start = std::chrono::steady_clock::now();
            scene.sail(1.0 / 60, boat_, double(rudder_));
            times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(times.begin(), times.end());
        return {{"wave_field_ms", times[times.size() / 2]}};
    }

    void read_input() {
        const ImGuiIO& io = ImGui::GetIO();
        key_rudder_ = 0;
        if (!io.WantCaptureKeyboard)
            key_rudder_ = double(ImGui::IsKeyDown(GLFW_KEY_RIGHT)) - double(ImGui::IsKeyDown(GLFW_KEY_LEFT));
        for (const ocean::InputEvent& press : frame_input().presses)
            if (press.code == ocean::input::kMouseLeft && !io.WantCaptureMouse && scene_) stones_.push_back(to_world(press.at));
    }

    // A window pixel (from the top left) to the world point under it (x, z).
    glm::dvec2 to_world(glm::dvec2 pixel) const {
        const ImGuiIO& io = ImGui::GetIO();
        const glm::dvec2 size(std::max(1.0f, io.DisplaySize.x), std::max(1.0f, io.DisplaySize.y));
        const glm::dvec2 uv(pixel.x / size.x, 1 - pixel.y / size.y);
        return view_centre() + (2.0 * uv - 1.0) * half_view();
    }
    glm::dvec2 view_centre() const {
        const step08::WaveField& f = scene_->field();
        return 0.5 * (f.cell_centre(0, 0) + f.cell_centre(f.n() - 1, f.n() - 1));
    }
    // The grid's side fills the window's height.
    glm::dvec2 half_view() const {
        const double half = 0.5 * scene_->field().side();
        return {half * aspect(), half};
    }

    void render() override {
        clear_target({0, 0, 0});
        if (!scene_) return;
        const step08::WaveField& f = scene_->field();
        if (heights_.id() == 0 || texture_cells_ != f.n()) {
            heights_ = ocean::make_float_texture_2d(GL_R32F, f.n(), f.n());
            texture_cells_ = f.n();
        }
        upload_.assign(f.heights().begin(), f.heights().end());
        ocean::upload_float_texture_2d(heights_, GL_R32F, f.n(), f.n(), upload_.data());
        ocean::ShaderProgram* p = program("wake", {"fullscreen.vert", "wake.frag"});
        if (p == nullptr) return;
        const glm::dvec2 centre = view_centre();
        p->set("u_cells", f.n());
        p->set("u_cell", float(f.settings().cell));
        p->set("u_first_cell", glm::vec2(f.cell_centre(0, 0) - centre));
        p->set("u_half_view", glm::vec2(half_view()));
        p->set("u_boat", glm::vec2(scene_->boat_position() - centre));
        p->set("u_heading", glm::vec2(scene_->boat_heading()));
        p->set("u_boat_length", float(boat_.length));
        p->set("u_relief", relief_);
        p->set("u_kelvin", kelvin_lines_ ? 1.0f : 0.0f);
        p->set("u_kelvin_angle", float(step08::kelvin_edge_angle(0.5)));  // deep water: c_g = c / 2
        p->set("u_pixels_high", float(framebuffer_size().y));
        p->set("u_show_field", show_field_ ? 1.0f : 0.0f);
        p->set("u_absorbing_width", float(f.settings().absorbing_width));
        ocean::bind_texture(0, GL_TEXTURE_2D, heights_.id());
        ocean::GpuScope timed(timers(), "wake");
        glUseProgram(p->id());
        draw_fullscreen_triangle();
    }

    void ui() override {
        if (!scene_) return;
        ImGui::Separator();
        const double froude = step08::froude_number(boat_.speed, boat_.length);
        ImGui::TextWrapped("Froude number U / sqrt(g L) = %.2f; transverse waves %.1f m long", froude,
                           step08::transverse_wavelength(boat_.speed));
        ImGui::TextWrapped("%s", froude < 0.6 ? "a Kelvin wake: its edge at 19.5 degrees"
                                              : "fast: the largest waves at a narrower angle, about 1 / Fr");
        ImGui::TextWrapped("arrows: turn the boat; left click: drop a stone");
        if (ImGui::Button("drop a stone ahead")) stones_.push_back(scene_->boat_position() + 10.0 * scene_->boat_heading());
    }

    step08::BoatSettings boat_;
    float rudder_ = 0, depth_ = 1000, cell_ = 0.5, warm_up_ = 20, relief_ = 8;
    int cells_choice_ = 1;
    bool show_field_ = false, kelvin_lines_ = false;
    double key_rudder_ = 0;
    std::unique_ptr<step08::WakeScene> scene_;
    std::vector<glm::dvec2> stones_;
    ocean::Texture heights_;
    int texture_cells_ = 0;
    std::vector<float> upload_;
};

}  // namespace

OCEAN_MAIN(Wakes)
