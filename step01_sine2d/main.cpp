// step01_sine2d: a sum of sines, plotted in 2D on the GPU.
// Notes sections 1.1, 1.2, 1.2.1.
// New: everything (this is the first step). Each wave is a_i sin(x w_i - t phi_i) with
// w = 2 pi / wavelength and phi = speed * 2 pi / wavelength; the plot shows each wave in its
// own colour and their sum in white, evaluated per pixel in plot.frag.
// Controls: the panel's sliders (per-wave wavelength, amplitude, speed), add/remove buttons; in
// the window, drag pans the plot and the wheel zooms it about the cursor (x_min, x_span).
#include "common/app.hpp"
#include "step01_sine2d/sine_sum.hpp"
#include "step01_sine2d/wave_params.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace {

constexpr int kMaxWaves = 8;  // MAX_WAVES in sine_sum.glsl

// Colours that stay apart on a dark background (the sum is drawn in white).
const std::array<glm::vec3, kMaxWaves> kWaveColors = {{
    {0.36f, 0.68f, 1.00f}, {1.00f, 0.55f, 0.25f}, {0.45f, 0.85f, 0.45f}, {0.90f, 0.40f, 0.75f},
    {0.95f, 0.85f, 0.30f}, {0.40f, 0.90f, 0.90f}, {0.75f, 0.55f, 1.00f}, {0.95f, 0.40f, 0.40f},
}};

class Sine2D : public ocean::App {
public:
    Sine2D()
        : App({"A sum of sines, in 2D", "1.1, 1.2, 1.2.1",
               "f(x,t) = sum of a_i sin(x w_i - t phi_i), with w = 2 pi / wavelength and "
               "phi = speed * 2 pi / wavelength. Each wave has its own colour; white is the sum."}) {
        // The parameters: the sum's (here), each wave's (step01::declare_wave, wave_params.hpp), the
        // plot's view (here).
        auto& p = params();
        p.add_int("wave_count", &wave_count_, 1, kMaxWaves, "number of waves in the sum");
        p.add_float("amplitude", &amplitude_, 0, 10, "scale applied to every wave's amplitude");
        // Deep-water-like defaults: longer waves are higher and faster (speed ~ sqrt(g L / 2 pi)).
        for (int i = 0; i < kMaxWaves; ++i) {
            const float wavelength = 9.0f * std::pow(0.62f, float(i));
            const float speed = std::sqrt(9.81f * wavelength / 6.2831853f) * (i % 3 == 1 ? -1.0f : 1.0f);
            waves_[i] = {wavelength, 0.8f * std::pow(0.6f, float(i)), speed};
            step01::declare_wave(p, i, waves_[i], {100, 5, 20, "crest speed, metres per second (negative: the other way)"},
                                 [this, i] { return i < wave_count_; });
        }
        p.add_float("x_min", &x_min_, -500, 500, "left edge of the plot, metres").in_group("view");
        p.add_float("x_span", &x_span_, 1, 1000, "metres across the plot").in_group("view").logarithmic();
        p.add_bool("show_waves", &show_waves_, "draw each wave in its own colour").in_group("view");
        p.add_bool("show_sum", &show_sum_, "draw the sum of the waves in white").in_group("view");
        p.add_bool("show_curvature", &show_curvature_, "draw the sum's curvature d2f/dx2 (1/m on the same axis), in pink")
            .in_group("view");
        p.add_float("line_width", &line_width_, 0.5f, 10, "width of a wave's line, pixels").in_group("view");
        offer_split_view([] {
            return SplitVariants{"each wave", "their sum", {"show_sum=false"}, {"show_waves=false"}};
        });
    }

private:

    void init() override { plot_ = program("plot", {"fullscreen.vert", "plot.frag"}); }

    void update(double /*time*/, double /*dt*/) override { pan_and_zoom(); }

    // The mouse moves the plot's window on x (a 2D step has no camera): a drag carries the curve
    // with the cursor, a wheel step zooms by 10% keeping the point under the cursor in place.
    // Through the registry, so the ranges hold and the panel's view sliders follow.
    void pan_and_zoom() {
        const FrameInput& input = frame_input();
        const double width = double(ImGui::GetIO().DisplaySize.x);  // window pixels, as the mouse's
        if (width <= 0 || (input.drag.x == 0 && input.scroll == 0 && !input.drag_ended)) return;
        ocean::Param& x_min = *params().find("x_min");
        ocean::Param& x_span = *params().find("x_span");
        const double metres_per_pixel = double(x_span_) / width;
        if (input.drag.x != 0) x_min.set_number(double(x_min_) - double(input.drag.x) * metres_per_pixel);
        if (input.scroll != 0) {
            const double fixed = double(x_min_) + input.cursor.x * metres_per_pixel;  // under the cursor
            const double before = double(x_span_);
            x_span.set_number(before * std::pow(0.9, double(input.scroll)));
            x_min.set_number(fixed - (fixed - double(x_min_)) * double(x_span_) / before);
        }
        // Where a drag or a wheel step left the plot, as the flags that start there.
        if (input.drag_ended || input.scroll != 0)
            std::cout << "plot: x from " << x_min_ << " to " << x_min_ + x_span_ << " m (--set x_min=" << x_min_
                      << " --set x_span=" << x_span_ << ")" << std::endl;
    }

    std::vector<step01::Wave> waves() const {
        std::vector<step01::Wave> out;
        for (int i = 0; i < wave_count_; ++i)
            out.push_back({waves_[i].wavelength, double(amplitude_) * waves_[i].amplitude, waves_[i].speed});
        return out;
    }

    void render() override {
        const auto list = waves();
        std::vector<glm::vec4> packed;
        double total_amplitude = 0;
        for (const auto& wave : list) {
            packed.emplace_back(float(step01::angular_wavenumber(wave)), float(wave.amplitude),
                                float(step01::phase_at(step01::phase_rate(wave), time())), 0.0f);
            total_amplitude += std::abs(wave.amplitude);
        }
        const glm::ivec2 size = framebuffer_size();
        plot_->set("u_wave_count", int(list.size()));
        plot_->set("u_waves", packed);
        plot_->set("u_resolution", glm::vec2(size));
        plot_->set("u_x_range", glm::vec2(x_min_, x_min_ + x_span_));
        // Leave a margin above the highest possible crest; never a zero-height plot.
        plot_->set("u_y_extent", float(std::max(1.25 * total_amplitude, 0.1)));
        plot_->set("u_show_waves", int(show_waves_));
        plot_->set("u_show_sum", int(show_sum_));
        plot_->set("u_show_curvature", int(show_curvature_));
        plot_->set("u_line_width", line_width_);
        plot_->set("u_wave_colors", std::vector<glm::vec3>(kWaveColors.begin(), kWaveColors.end()));

        ocean::GpuScope timed(timers(), "plot");
        glUseProgram(plot_->id());
        draw_fullscreen_triangle();
    }

    void ui() override {
        ImGui::Separator();
        if (ImGui::Button("add a wave") && wave_count_ < kMaxWaves) {
            ++wave_count_;
        }
        ImGui::SameLine();
        if (ImGui::Button("remove a wave") && wave_count_ > 1) {
            --wave_count_;
        }
        for (int i = 0; i < wave_count_; ++i)
            ImGui::TextColored(ImVec4(kWaveColors[i].r, kWaveColors[i].g, kWaveColors[i].b, 1),
                               "wave %d: w = %.3f rad/m, phi = %.3f rad/s", i,
                               step01::kTwoPi / double(waves_[i].wavelength),
                               double(waves_[i].speed) * step01::kTwoPi / double(waves_[i].wavelength));
    }

    ocean::ShaderProgram* plot_ = nullptr;
    int wave_count_ = 3;
    float amplitude_ = 1;
    std::array<step01::WaveSliders, kMaxWaves> waves_{};
    float x_min_ = -4, x_span_ = 32, line_width_ = 2;
    bool show_waves_ = true, show_sum_ = true, show_curvature_ = false;
};

}  // namespace

OCEAN_MAIN(Sine2D)
