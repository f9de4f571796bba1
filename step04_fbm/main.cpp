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
        auto& p = params();
        p.add_choice("shape", &shape_, {"sine", "exp_sine"},
                     "wave shape: sin(x), or exp(sin(x) - 1) with sharp crests and flat troughs").in_group("fbm");
        p.add_int("wave_count", &wave_count_, 1, step04::kMaxWavesPerCascade, "waves in each cascade")
            .in_group("fbm");
        p.add_float("base_wavelength", &base_wavelength_, 1, 500, "wavelength of wave 0, metres")
            .in_group("fbm").logarithmic();
        p.add_float("amplitude", &amplitude_, 0, 10, "amplitude of wave 0 (a0), metres").in_group("fbm");
        p.add_float("gain", &gain_, 0, 1, "amplitude ratio of neighbouring waves").in_group("fbm");
        p.add_float("lacunarity", &lacunarity_, 1, 3, "frequency ratio of neighbouring waves")
            .in_group("fbm");
        p.add_float("speed_scale", &speed_scale_, 0, 5,
                    "a factor on every wave's phase rate: 1 = deep water, phi = sqrt(g w) (step01's speed is m/s)")
            .in_group("fbm");
        p.add_int("seed", &seed_, 0, 1000000, "seed of the wave directions").in_group("fbm");
        p.add_float("warp", &warp_, 0, 10,
                    "domain warping strength s: each wave pushes the next ones' input by s a grad f")
            .in_group("fbm");
        p.add_int("cascade_count", &cascade_count_, 1, step04::kMaxCascades, "independent sums layered")
            .in_group("cascades");
        p.add_float("cascade_ratio", &cascade_ratio_, 0.05f, 0.95f,
                    "base wavelength and amplitude of cascade c: ratio^c times cascade 0's")
            .in_group("cascades");
        p.add_choice("view", &view_, {"lit", "diffuse", "specular", "normals"},
                     "the whole light, one term alone, or the normals as colours").in_group("light");
        light_.declare(p);
        grid_params_.declare(p);
        p.add_bool("wireframe", &wireframe_, "draw the triangles' edges only").in_group("view");
        use_camera(ocean::camera_view("overview"));
    }

private:
    void init() override { fbm_uniforms_ = std::make_unique<step04::FbmUniforms>(); }

    void update(double /*time*/, double /*dt*/) override {
        grid_params_.update(grid_);
        if (params().generation() != cascades_generation_) {  // waves only change with the parameters
            step04::CascadeSettings s;
            s.wave_count = wave_count_;
            s.base_wavelength = base_wavelength_;
            s.base_amplitude = amplitude_;
            s.gain = gain_;
            s.lacunarity = lacunarity_;
            s.speed_scale = speed_scale_;
            s.seed = std::uint64_t(seed_);
            cascades_ = step04::make_cascades(s, cascade_count_, cascade_ratio_);
            cascades_generation_ = params().generation();
        }
    }

    void render() override {
        const glm::vec3 clear = step03::LightParams::background_srgb();
        clear_target(clear);
        ocean::ShaderProgram* ocean = program("ocean", {"ocean.vert", "ocean.frag"},
                                              {"SHAPE " + std::to_string(shape_), "VIEW " + std::to_string(view_)});
        fbm_uniforms_->upload(*ocean, cascades_, warp_, time());
        step03::upload_light(*ocean, light_.light());
        ocean->set("u_wireframe", int(wireframe_));
        ocean->set("u_background", step03::srgb_to_linear(clear));
        draw_grid(*ocean, grid_, wireframe_);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d waves in %d cascade(s); %d vertices", wave_count_ * cascade_count_, cascade_count_,
                    grid_.vertex_count());
        for (std::size_t c = 0; c < cascades_.size(); ++c) {
            const auto& w = cascades_[c].waves;
            ImGui::Text("cascade %zu: wavelengths %.2f m .. %.3f m", c, step04::kTwoPi / w.front().wavenumber,
                        step04::kTwoPi / w.back().wavenumber);
        }
    }

    std::optional<SplitVariants> split_variants() const override {
        return SplitVariants{"sine", "exp(sin - 1)", {"shape=sine"}, {"shape=exp_sine"}};
    }

    std::unique_ptr<step04::FbmUniforms> fbm_uniforms_;  // made once the GL context exists
    ocean::GridMesh grid_;
    ocean::GridParams grid_params_;
    step03::LightParams light_;
    std::vector<step04::Cascade> cascades_;
    unsigned cascades_generation_ = ~0u;
    int shape_ = int(step04::Shape::ExpSine), wave_count_ = 20, seed_ = 1, cascade_count_ = 2, view_ = 0;
    float base_wavelength_ = 40, amplitude_ = 1.2f, gain_ = 0.82f, lacunarity_ = 1.18f, speed_scale_ = 1;
    float warp_ = 4, cascade_ratio_ = 0.37f;
    bool wireframe_ = false;
};

}  // namespace

OCEAN_MAIN(Fbm)
