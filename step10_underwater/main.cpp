// step10_underwater: the sea from below.
// Beyond the notes: every chapter so far looked at the sea from above.
// New since step06: below the mean level the camera sees the surface from the water's side
// (Snell's window: the whole sky squeezed into a cone of half-angle 48.6 degrees, the depths
// mirrored outside it), the water's own colour (absorption and scattering per colour, Beer and
// Lambert), and a seabed lit through caustics that the moving surface focuses.
// Controls: as step06 (drag, wheel, C for the fly camera: dive and surface with it).
//
// The program is step06's SeaScene (the sea, the sky, the sea renderer, the image passes), with
// two parts of its own: Underwater (underwater.hpp), which takes over two moments of the frame
// while the camera is below the surface, and Waterline (waterline.hpp), which decides which side
// each pixel is drawn from and puts the two pictures together when the lens is at the surface.
#include "common/app.hpp"
#include "step06_foam_sky/sea_scene.hpp"
#include "step10_underwater/underwater.hpp"
#include "step10_underwater/waterline.hpp"

#include <imgui.h>

#include <algorithm>

namespace {

class UnderwaterProgram : public ocean::App {
public:
    UnderwaterProgram()
        : App({"Under the water", "",
               "The sea from below: the sky through Snell's window, the depths mirrored beyond it, the "
               "water's colour with depth, and caustics the waves focus on the seabed.",
               /*window_samples=*/0}) {
        ocean::ParamRegistry& p = params();
        scene_.declare(p);
        underwater_.declare(p);
        waterline_.declare(p);
        {
            const auto group = p.group("underwater");
            p.add_float("dive_speed", &dive_speed_, -2, 2,
                        "metres a second the camera sinks (negative: rises), through the surface and back");
        }
        // A high sun, as divers choose: its beam reaches the seabed through less water, and the
        // caustics it draws there are sharp.
        p.set_default("sun_elevation", 45.0);
        // 4 m down, looking up at 30 degrees: the edge of Snell's window (41.4 degrees above the
        // horizontal) is in the picture.
        use_camera({{0, -1, 0}, 6, 35, -30}, ocean::kOceanReach);
#ifndef OCEAN_GL_PORTABLE  // step05's backends: GL 4.5 only
        offer_bench_figures([this] { return scene_.sea().time_backends(time()); });
        offer_warm_up([this] { return scene_.sea().choosing_backend(); });
#endif
    }

private:
    void init() override {
        scene_.init(program_factory());
        underwater_.init(program_factory());
        waterline_.init(program_factory());
    }

    void update(double time, double dt) override {
        // A dive: the camera's target sinks (or rises) at dive_speed, stopping half a metre above
        // the seabed.
        if (dive_speed_ != 0) {
            ocean::Camera& c = camera();
            c.target.y = std::max(c.target.y - double(dive_speed_) * dt, 0.5 - double(underwater_.seabed_depth()));
        }
        scene_.update(time, dt, camera(), timers());
    }

    // Above the waves, step06's frame; below them, the same frame with this chapter's additions;
    // with the lens within the waves' reach of the surface, both, put together along the waterline.
    void render() override {
        const step06::Sea& sea = scene_.sea();
        const glm::vec3 eye(camera().eye_world() - sea.world_origin());
        sides_ = step10::sides_reached(camera(), aspect(), sea.world_origin(), step10::water_reach(sea));
        const glm::mat4 view_projection = camera().projection(aspect()) * camera().view(sea.world_origin());
        if (waterline_.shows_sides()) {
            waterline_.paint_sides(sea, view_projection, sides_, fullscreen_vao());
            return;
        }
        const step06::SceneView onto_screen{camera(), framebuffer_size(), aspect(), fullscreen_vao(), [this] { bind_target(); }};
        if (sides_ != step10::Sides::below) scene_.render(onto_screen, timers());
        if (sides_ == step10::Sides::above) return;
        underwater_.update_caustics(scene_, eye, timers());
        const glm::ivec2 size = framebuffer_size();
        const step06::SceneView below_only{camera(), size, aspect(), fullscreen_vao(),
                                           [this, size] { waterline_.bind_below_target(size); }};
        scene_.render(sides_ == step10::Sides::below ? onto_screen : below_only, timers(),
                      underwater_.additions(scene_, eye, fullscreen_vao()));
        if (sides_ == step10::Sides::below) return;
        ocean::GpuScope timed(timers(), "waterline");
        bind_target();
        waterline_.compose(sea, view_projection, fullscreen_vao());
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%s, seabed %.0f m down", underwater_.water().name, double(underwater_.seabed_depth()));
        const char* drawn[] = {"above the water", "below the water", "across the waterline"};
        ImGui::Text("The lens is %s.", drawn[int(sides_)]);
    }

    step06::SeaScene scene_;
    step10::Underwater underwater_;
    step10::Waterline waterline_;
    step10::Sides sides_ = step10::Sides::above;
    float dive_speed_ = 0;
};

}  // namespace

OCEAN_MAIN(UnderwaterProgram)
