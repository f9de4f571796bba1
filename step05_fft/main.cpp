// step05_fft: an ocean from a wave spectrum, transformed by an FFT on the GPU.
// Notes sections 4.1-4.5.
// New since step04: instead of summing waves one by one, a JONSWAP (or Phillips) spectrum gives
// every wave of an N x N grid of wavenumbers an amplitude h0(k) (spectrum.cpp); each frame the
// modes turn at omega(k) (evolve.comp) and an inverse FFT turns them into height, choppy
// displacement and slope maps (fft.comp: Stockham in shared memory), which displace the grid.
// Three transform backends to compare: the notes' naive DFT, the GPU FFT, and FFTW on the CPU.
// Without compute shaders (the portable profile: macOS, the browser) the same passes run as
// fragment passes (fragment_simulation.hpp) and there is no backend to choose: the profile is
// chosen once, in sea_simulation.hpp and transform_choice.hpp, not here.
// Controls: as step02; the panel's "spectrum" group, the backend and the map views.
#include "common/app.hpp"
#include "common/constants.hpp"
#include "common/gl_texture.hpp"
#include "common/grid.hpp"
#include "step03_lighting/light_params.hpp"
#include "step03_lighting/light_uniforms.hpp"
#include "step05_fft/export.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/ocean_params.hpp"
#include "step05_fft/sea_simulation.hpp"
#include "step05_fft/spectrum_view.hpp"
#include "step05_fft/transform_choice.hpp"

#include <imgui.h>

#include <cmath>
#include <memory>

namespace {

class FftOcean : public ocean::App {
public:
    FftOcean()
        : App({"An FFT ocean", "4.1-4.5",
               "A JONSWAP spectrum gives each of N x N waves an amplitude; every frame the modes turn "
               "at omega = sqrt(g k tanh(k h)) and one inverse FFT per map (on the GPU, all stages in "
               "shared memory) gives heights, choppy displacements and slopes."}) {
        // The parameters: the spectrum (ocean_params.hpp), the backend, normals and views (here),
        // step03's light (step03_lighting/light_params.hpp), the grid (common/grid.hpp), the camera
        // (common/camera.cpp).
        auto& p = params();
        ocean_params_.declare(p);
        offer_transforms();  // GL 4.5 only: the transform's parameters, benchmark and split view
        p.add_choice("sea", &sea_, {"spectrum", "gerstner"},
                     "the FFT's sea, or one Gerstner wave in closed form along the wind (section 4)");
        p.add_float("gerstner_wavelength", &gerstner_.wavelength, 1, 500, "sea=gerstner: the wave's length, m")
            .in_group("gerstner");
        p.add_float("gerstner_amplitude", &gerstner_.amplitude, 0, 20, "sea=gerstner: the wave's amplitude A, m")
            .in_group("gerstner");
        p.add_float("gerstner_steepness", &gerstner_.steepness, 0, 1.5,
                    "sea=gerstner: Q k A, how far points move towards the crest (GPU Gems' Q): 1 is a cusp, "
                    "above 1 the crest folds over itself")
            .in_group("gerstner");
        p.add_choice("normals", &normals_, {"slopes", "finite_difference"},
                     "normals from the slope maps (i k h~) or from differences of the height map");
        std::vector<std::string> views = step05::map_view_names();  // view 1.. is map view 0..
        views.insert(views.begin(), "shaded");
        views.push_back("spectrum");
        p.add_choice("view", &view_, views, "the lit sea, or one map over the screen");
        p.add_float("map_range", &map_range_, 0, 100,
                    "value shown at full colour in the map views but the Jacobian's (0: chosen from the spectrum)");
        light_.declare(p);
        grid_params_.declare(p);
        p.add_bool("wireframe", &wireframe_, "draw the triangles' edges only").in_group("view");
        p.add_bool("frustum_culling", &cull_, "draw only the grid's chunks that may be in view").in_group("grid");
        use_camera(ocean::camera_view("deck"));  // an open sea, seen from a ship's deck (12 m up)
        // --export DIR: this frame's maps as PFM files and a list of the parameters (export.hpp).
        offer_export([this](const std::string& dir) {
            step05::export_maps(dir, simulation_->displacement_texture(), simulation_->slopes_texture(), 0,
                                simulation_->resolution(),
                                ocean_params_.spectrum.patch_size, time(), ocean_params_.choppiness, params());
        });
    }

private:
    void init() override {
        simulation_ = std::make_unique<step05::SeaSimulation>(program_factory());
    }

    // A new spectrum when one of its parameters moved, then the maps at `time`.
    void update(double time, double /*dt*/) override {
        grid_params_.update(grid_);
        if (spectrum_made_for_ != ocean_params_.changes.value) {
            spectrum_made_for_ = ocean_params_.changes.value;
            const step05::SpectrumParams& wanted = ocean_params_.spectrum;
            spectrum_ = std::make_unique<step05::InitialSpectrum>(step05::initial_spectrum(wanted));
            simulation_->set_spectra({spectrum_.get()});
            spectrum_view_.update(wanted, *spectrum_);
            height_variance_ = step05::resolved_variance(wanted);
        }
        transforms_.simulate(*simulation_, time, ocean_params_.choppiness, timers());
    }

    void render() override {
        const glm::vec3 clear = step03::LightParams::background_srgb();
        clear_target(clear);
        if (view_ > 0) {
            draw_map_view();
            return;
        }
        ocean::ShaderProgram* ocean_program = program("ocean", {"ocean.vert", "ocean.frag"},
                                                      {"NORMALS " + std::to_string(normals_), "SEA " + std::to_string(sea_)});
        if (sea_ == 1) set_gerstner_wave(*ocean_program);
        step03::upload_light(*ocean_program, light_.light());
        ocean_program->set("u_patch_size", float(ocean_params_.spectrum.patch_size));
        ocean_program->set("u_resolution", ocean_params_.spectrum.resolution);
        ocean_program->set("u_wireframe", int(wireframe_));
        ocean_program->set("u_background", step03::srgb_to_linear(clear));
        simulation_->bind_maps(*ocean_program);
        // Only the grid's chunks that may be in view (the plane reaches the horizon all round, the
        // view sees a wedge of it), widened by how far a vertex can move.
        double margin = step05::largest_displacement(height_variance_, ocean_params_.choppiness);
        if (sea_ == 1) margin = gerstner_.amplitude + gerstner_.steepness / gerstner_wavenumber() + 1;  // A + Q A
        ocean::draw_grid(grid_, *ocean_program, camera(), aspect(), timers(), wireframe_, cull_ ? float(margin) : -1.0f);
    }

    double gerstner_wavenumber() const { return 2 * ocean::kPi / double(gerstner_.wavelength); }

    // sea=gerstner's one wave, along the wind. The shader takes Q itself: Q = steepness / (k A).
    void set_gerstner_wave(const ocean::ShaderProgram& p) const {
        const step05::SpectrumParams& s = ocean_params_.spectrum;
        const double k = gerstner_wavenumber(), amplitude = gerstner_.amplitude;
        const double direction = s.wind_direction * ocean::kPi / 180;
        p.set("u_gerstner", glm::vec4(float(std::cos(direction)), float(std::sin(direction)), float(k), float(amplitude)));
        p.set("u_gerstner_steepness", float(gerstner_.steepness / std::max(k * amplitude, 1e-9)));
        p.set("u_gerstner_phase", float(step05::reduced_phase(step05::dispersion(k, s.depth), time())));
    }

    void draw_map_view() {
        ocean::ShaderProgram* p = program("map_view", {"fullscreen.vert", "map_view.frag"});
        if (p == nullptr) return;  // first asked for after a shader broke: nothing to draw with
        const int map = view_ - 1;
        float range = map_range_;
        if (range <= 0) {  // about 2.5 standard deviations of the height; slopes within 0.5 (J: its own scale)
            range = map <= 2 ? std::max(2.5f * float(std::sqrt(height_variance_)), 1e-3f) : 0.5f;
        }
        p->set("u_map", map);
        p->set("u_range", range);
        p->set("u_resolution", glm::vec2(framebuffer_size()));
        simulation_->bind_maps(*p);
        p->set("u_spectrum_image", 3);
        ocean::bind_texture(3, GL_TEXTURE_2D, spectrum_view_.texture());
        glUseProgram(p->id());
        draw_fullscreen_triangle();
    }

    void ui() override {
        ImGui::Separator();
        spectrum_view_.draw_ui();
        transforms_.ui(*simulation_, time());
    }

    // The transform's parameters, --bench's table of the backends against FFTW's floor, the
    // warm-up while auto decides, and the split view of the notes' DFT against the GPU FFT: where
    // the build has transforms to choose between (transform_choice.hpp).
    void offer_transforms() {
        transforms_.declare(params());
        if (!step05::TransformChoice::kOffered) return;
        offer_bench_figures([this] { return transforms_.bench_figures(*simulation_, time()); });
        offer_warm_up([this] { return transforms_.warming_up(simulation_.get()); });
        offer_split_view([this] { return transforms_.split_variants(ocean_params_.spectrum.resolution); });
    }

    step05::OceanParams ocean_params_;
    step03::LightParams light_;
    ocean::GridParams grid_params_{800, 400};  // several tiles: the sea reaches the horizon
    step05::TransformChoice transforms_;
    std::unique_ptr<step05::SeaSimulation> simulation_;
    std::unique_ptr<step05::InitialSpectrum> spectrum_;
    unsigned spectrum_made_for_ = 0;  // ocean_params_.changes when the spectrum was made
    step05::SpectrumView spectrum_view_;
    ocean::GridMesh grid_;
    bool cull_ = true;
    int normals_ = 0, view_ = 0, sea_ = 0;
    float map_range_ = 0;
    struct {
        float wavelength = 24, amplitude = 1.2f, steepness = 0.8f;  // k A = 0.31: a steep wind wave
    } gerstner_;
    double height_variance_ = 0;  // m^2: the spectrum's resolved variance
    bool wireframe_ = false;
};

}  // namespace

OCEAN_MAIN(FftOcean)
