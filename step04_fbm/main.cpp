// step04_fbm: many waves without the hand-tuning: fractional Brownian motion, sharper crests,
// domain warping, and cascades of sums.
// Notes sections 3, 3.1-3.3, and 4's cascading of sums.
// New since step03: the wave shape exp(sin - 1) with its exact derivative; fBm (wave i has
// amplitude a0 gain^i, frequency w0 lacunarity^i, a seeded random direction, deep-water speed);
// domain warping with an exact normal (the chain rule through the warp); up to 4 cascades.
// Controls: as step02; the panel's "fbm", "cascades" and "light" groups.
#include "common/app.hpp"
#include "common/grid.hpp"
#include "step03_lighting/light_params.hpp"
#include "step03_lighting/light_uniforms.hpp"
#include "step04_fbm/fbm_params.hpp"
#include "step04_fbm/fbm_uniforms.hpp"

#include <imgui.h>

#include <memory>

namespace {

class Fbm : public ocean::App {
public:
    Fbm()
        : App({"fBm waves", "3, 3.1-3.3, 4 (cascades)",
               "Wave i of a cascade has amplitude a0 gain^i and frequency w0 lacunarity^i (0.82, 1.18), a "
               "random direction and deep-water speed; exp(sin - 1) sharpens the crests; domain warping "
               "moves each wave's input downhill of the waves before it, with an exact normal; cascades "
               "with different base wavelengths hide the repeats."}) {
        // The parameters: the fBm and its cascades (fbm_params.hpp), the view (here), step03's light
        // (step03_lighting/light_params.hpp), the grid (common/grid.hpp), the camera (common/camera.cpp).
        auto& p = params();
        fbm_.declare(p);
        p.add_choice("view", &view_, {"lit", "diffuse", "specular", "normals"},
                     "the whole light, one term alone, or the normals as colours").in_group("light");
        light_.declare(p);
        grid_params_.declare(p);
        p.add_bool("wireframe", &wireframe_, "draw the triangles' edges only").in_group("view");
        use_camera(ocean::camera_view("overview"));
        offer_split_view([] {
            return SplitVariants{"sine", "exp(sin - 1)", {"shape=sine"}, {"shape=exp_sine"}};
        });
    }

private:
    void init() override { fbm_uniforms_ = std::make_unique<step04::FbmUniforms>(); }

    void update(double /*time*/, double /*dt*/) override {
        grid_params_.update(grid_);
        if (fbm_.changes.value != waves_made_for_) {  // only a wave parameter makes new waves
            cascades_ = fbm_.make();
            waves_made_for_ = fbm_.changes.value;
        }
    }

    void render() override {
        const glm::vec3 clear = step03::LightParams::background_srgb();
        clear_target(clear);
        ocean::ShaderProgram* ocean_program = program("ocean", {"ocean.vert", "ocean.frag"},
                                              {"SHAPE " + std::to_string(fbm_.shape), "VIEW " + std::to_string(view_)});
        fbm_uniforms_->upload(*ocean_program, cascades_, fbm_.warp, time());
        step03::upload_light(*ocean_program, light_.light());
        ocean_program->set("u_wireframe", int(wireframe_));
        ocean_program->set("u_background", step03::srgb_to_linear(clear));
        ocean::draw_grid(grid_, *ocean_program, camera(), aspect(), timers(), wireframe_);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d waves in %d cascade(s); %d vertices", fbm_.wave_count * fbm_.cascade_count, fbm_.cascade_count,
                    grid_.vertex_count());
        for (std::size_t c = 0; c < cascades_.size(); ++c) {
            const auto& w = cascades_[c].waves;
            ImGui::Text("cascade %zu: wavelengths %.2f m .. %.3f m", c, step04::kTwoPi / w.front().wavenumber,
                        step04::kTwoPi / w.back().wavenumber);
        }
    }

    std::unique_ptr<step04::FbmUniforms> fbm_uniforms_;  // made once the GL context exists
    ocean::GridMesh grid_;
    ocean::GridParams grid_params_;
    step03::LightParams light_;
    std::vector<step04::Cascade> cascades_;
    step04::FbmParams fbm_;  // the waves' parameters (fbm_params.hpp)
    unsigned waves_made_for_ = 0;  // changes starts at 1: the first frame builds
    int view_ = 0;
    bool wireframe_ = false;
};

}  // namespace

OCEAN_MAIN(Fbm)
