// A new chapter, copied from step_template by `./ocean new stepNN_name` (README, "Adding a
// chapter"). It draws one travelling wave as a band of colour, to be replaced by the chapter's own
// technique: declare the parameters in the constructor, simulate in update(), draw in render().
#include "common/app.hpp"
#include "chapter.hpp"

#include <imgui.h>

namespace {

// The title, the notes' sections and the paragraph the panel shows.
ocean::StepInfo chapter_info() {
    return {"A new chapter", "",
            "The template every chapter starts from: one travelling wave, h = a sin(w (x - c t)), drawn as a "
            "band of colour. Replace it with the chapter's technique."};
}

class Chapter : public ocean::App {
public:
    Chapter() : App(chapter_info()) {
        // Each parameter bound to its member; the member's initialiser (below) is the default.
        ocean::ParamRegistry& p = params();
        p.add_float("amplitude", &amplitude_, 0, 10, "wave amplitude, metres");
        p.add_float("wavelength", &wavelength_, 0.5f, 100, "distance between crests, metres").logarithmic();
        p.add_float("speed", &speed_, -20, 20, "crest speed towards +x, metres per second");
        p.add_float("x_span", &x_span_, 1, 1000, "metres of x across the screen");
    }

private:
    step10::Wave wave() const { return {wavelength_, amplitude_, speed_}; }

    void render() override {
        clear_target({0, 0, 0});
        ocean::ShaderProgram* p = program("chapter", {"fullscreen.vert", "chapter.frag"});
        const step10::Wave w = wave();
        p->set("u_wavenumber", float(ocean::kTwoPi / w.wavelength));
        p->set("u_amplitude", float(w.amplitude));
        p->set("u_phase", float(step10::phase(w, time())));
        p->set("u_x_span", x_span_);
        ocean::GpuScope timed(timers(), "chapter");
        glUseProgram(p->id());
        draw_fullscreen_triangle();
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("h(0, t) = %.3f m", step10::height(wave(), 0, time()));
    }

    float amplitude_ = 1, wavelength_ = 8, speed_ = 2, x_span_ = 32;
};

}  // namespace

OCEAN_MAIN(Chapter)
