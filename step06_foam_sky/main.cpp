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
// The program is four parts, each in its own file, composed here in the order a frame runs them:
//   Sea          sea.hpp           the cascades' simulation and the foam
//   Sky          sky.hpp           the sky cubemap, and the background
//   SeaRenderer  sea_renderer.hpp  the tessellated mesh into a G-buffer, then the shading
//   PostProcess  post.hpp          bloom and the tonemapper
// and LookParams (look_params.hpp), the light, water and image parameters they share.
#include "common/app.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/sea_renderer.hpp"
#include "step06_foam_sky/sky.hpp"

#include <imgui.h>

#include <memory>

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
        // The parameters, in the order a frame uses them: the sea (spectrum, cascades, foam), the
        // mesh and the view, then the sky, the water's light and the image passes.
        ocean::ParamRegistry& p = params();
        sea_.declare(p);
        renderer_.declare(p);
        look_.declare(p);
        std::vector<std::string> split_choices;
        for (step06::Effect e : step06::kSplitEffects) split_choices.emplace_back(step06::effect_name(e));
        p.add_choice("split_effect", &split_effect_, split_choices,
                     "split view: the effect shown on the left and left out on the right");
        // 5 m above the water, level with the crests; anywhere on an ocean (camera-relative rendering).
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_services();
    }

private:
    void init() override {
        sea_.init(program_factory());
        sky_ = std::make_unique<step06::Sky>(program_factory(), 128);
        renderer_.init(program_factory());
        post_.init(program_factory());
    }

    // Once a frame, whatever the split view shows: the sea, its foam and the sky move on.
    void update(double time, double dt) override {
        const glm::dvec3 eye = camera().eye_world();
        {
            ocean::GpuScope timed(timers(), "simulation");
            sea_.simulate(time, eye);
        }
        {
            ocean::GpuScope timed(timers(), "foam");
            sea_.update_foam(dt, eye, camera().forward());
        }
        ocean::GpuScope timed(timers(), "sky");
        sky_->update(look_.sky(time, sea_.wind_direction()), look_.sky_image, look_.sky_image_changes.value);
    }

    // The frame into the HDR scene, then to the screen. Camera-relative: the view, the mesh and
    // the shading work in metres from the sea's world origin near the camera, so their float
    // positions stay small anywhere on the ocean.
    void render() override {
        post_.begin(framebuffer_size());
        const glm::mat4 view_projection = camera().projection(aspect()) * camera().view(sea_.world_origin());
        {
            ocean::GpuScope timed(timers(), "ocean");
            renderer_.draw(sea_, *sky_, look_,
                           {view_projection, camera().eye_world(), framebuffer_size(), post_.scene_framebuffer(),
                            post_.depth_texture(), fullscreen_vao()});
        }
        {
            ocean::GpuScope timed(timers(), "background");
            sky_->draw_background(view_projection, fullscreen_vao());
        }
        const step06::PostSettings image = look_.post(renderer_.view() == step06::kViewShaded);
        {
            ocean::GpuScope timed(timers(), "bloom");
            post_.bloom(image, fullscreen_vao());
        }
        ocean::GpuScope timed(timers(), "tonemap");
        bind_target();
        post_.tonemap(image, fullscreen_vao());
    }

    void ui() override {
        ImGui::Separator();
        for (const auto& line : sea_.description()) ImGui::TextUnformatted(line.c_str());
        ImGui::Text("%d patches of %.0f m; sky %s", renderer_.patch_count(), double(renderer_.patch_size()),
                    sky_->uses_image() ? "from an image" : "procedural");
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
            sea_.export_surface(dir, programs, time(), params());
        });
        offer_bench_figures([this] { return sea_.time_backends(time()); });
        offer_warm_up([this] { return sea_.choosing_backend(); });
#endif
    }

    step06::Sea sea_;
    std::unique_ptr<step06::Sky> sky_;
    step06::SeaRenderer renderer_;
    step06::PostProcess post_;
    step06::LookParams look_;
    int split_effect_ = 0;
};

}  // namespace

OCEAN_MAIN(FoamSky)
