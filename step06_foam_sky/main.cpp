// step06_foam_sky: the open sea under a sky.
// Notes sections 5, 5.1-5.6.
// New since step05: four cascades of step05's simulation, each with its own tile and band of
// wavenumbers, transformed together; GPU tessellation of patches around the camera with frustum
// culling, shaded once per pixel (deferred); foam where the surface folds, kept and faded with
// time; water shading with subsurface scatter, GGX or Beckmann specular and the sky's reflection
// through Fresnel; a sky cubemap with sun and drifting clouds; height fog, bloom and a filmic
// tonemapper, in HDR.
// Controls: as step02 (drag, wheel, C for the fly camera); every term and pass in the panel.
//
// The program is four parts, each in its own file, and the parameters they share:
//   Sea          sea.hpp           the cascades' simulation and the foam
//   Sky          sky.hpp           the sky cubemap, and the background
//   SeaRenderer  sea_renderer.hpp  the tessellated mesh into a G-buffer, then the shading
//   PostProcess  post.hpp          bloom and the tonemapper
//   LookParams   look_params.hpp   the light, water and image parameters
// composed in the order a frame runs them by a SeaScene (sea_scene.hpp): its update() moves the
// sea, the foam and the sky on; its render() draws the sea, the sky behind it, bloom, the tonemapper.
#include "common/app.hpp"
#include "step06_foam_sky/sea_scene.hpp"

#include <imgui.h>

namespace {

class FoamSky : public ocean::App {
public:
    FoamSky()
        : App({"Foam and sky", "5, 5.1-5.6",
               "Four cascades of the FFT ocean (each its own band of waves), tessellated near the camera; foam "
               "where the Jacobian folds the surface; scatter + microfacet specular + sky reflection with "
               "Fresnel; a sky with sun and clouds; fog, bloom and a filmic tonemapper.",
               // The scene is drawn off-screen in HDR and reaches the window in the tonemapper's one
               // full-screen triangle: a multisampled window would only cost.
               /*window_samples=*/0}) {
        ocean::ParamRegistry& p = params();
        scene_.declare(p);
        std::vector<std::string> split_choices;
        for (step06::Effect e : step06::kSplitEffects) split_choices.emplace_back(step06::effect_name(e));
        p.add_choice("split_effect", &split_effect_, split_choices,
                     "split view: the effect shown on the left and left out on the right");
        // 5 m above the water, level with the crests; anywhere on an ocean (camera-relative rendering).
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_services();
    }

private:
    void init() override { scene_.init(program_factory()); }

    // Once a frame, whatever the split view shows: the sea, its foam and the sky move on.
    void update(double time, double dt) override { scene_.update(time, dt, camera(), timers()); }

    // The frame: the sea into the HDR scene, the sky behind it, bloom, then the tonemapper to the
    // screen (twice a frame with the split view, once per variant).
    void render() override {
        scene_.render({camera(), framebuffer_size(), aspect(), fullscreen_vao(), [this] { bind_target(); }},
                      timers());
    }

    void ui() override {
        ImGui::Separator();
        for (const auto& line : scene_.sea().description()) ImGui::TextUnformatted(line.c_str());
        ImGui::Text("%d patches of %.0f m; sky %s", scene_.renderer().patch_count(),
                    double(scene_.renderer().patch_size()), scene_.sky().uses_image() ? "from an image" : "procedural");
    }

    // The framework's services: the split view (one effect with and without), and in the GL 4.5
    // profile --export (the rendered surface and its foam, gathered by a compute pass) and
    // --bench's extra figures (the FFT backends).
    void offer_services() {
        offer_split_view([this] {
            const std::string effect = step06::effect_name(step06::kSplitEffects[split_effect_]);
            return SplitVariants{"with " + effect, "without " + effect, {"show_" + effect + "=true"},
                                 {"show_" + effect + "=false"}};
        });
#ifndef OCEAN_GL_PORTABLE
        offer_export([this](const std::string& dir) {
            ocean::ProgramFactory programs = program_factory();
            scene_.sea().export_surface(dir, programs, time(), params());
        });
        offer_bench_figures([this] { return scene_.sea().time_backends(time()); });
        offer_warm_up([this] { return scene_.sea().choosing_backend(); });
#endif
    }

    step06::SeaScene scene_;
    int split_effect_ = 0;
};

}  // namespace

OCEAN_MAIN(FoamSky)
