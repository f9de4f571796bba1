// lab_compute_shading: step06's frame with its shading pass as a compute shader, a thread a pixel,
// where step06 runs a fragment shader over a full-screen triangle.
//
// Why it is worth measuring: a GPU built for compute runs fragment shaders on the few of its units
// that can do graphics, and compute shaders on all of them; there the same shading runs many times
// faster (docs/performance.md, "What left step06"). On a machine whose rasteriser is strong, or in
// software, the fragment shader is as fast or faster, and the lesson teaches the fragment shader.
// The two draw the same picture (draws_what_step06_draws.sh); `./ocean bench --lab compute_shading`
// times them side by side.
//
// The program is step06's parts, composed as step06's main.cpp composes them, with one pass
// changed: the mesh still records the G-buffer (SeaRenderer::record), then shaders/ocean_shade.comp
// shades it with step06's own shading (ocean_shade.glsl) and the same inputs
// (SeaRenderer::bind_shading).
#include "common/app.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/sea_renderer.hpp"
#include "step06_foam_sky/sky.hpp"

#include <memory>

namespace {

// The scene's depth for ocean_shade.comp (UNIT_GBUFFER_DEPTH there): a unit step06's table
// (texture_units.h) leaves free.
constexpr GLuint kDepthUnit = 8;

class ComputeShading : public ocean::App {
public:
    ComputeShading()
        : App({"step06 with compute shading", "", "step06's frame with its shading pass as a compute shader.",
               /*window_samples=*/0}) {
        ocean::ParamRegistry& p = params();
        sea_.declare(p);
        renderer_.declare(p);
        look_.declare(p);
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_bench_figures([this] { return sea_.time_backends(time()); });
        offer_warm_up([this] { return sea_.choosing_backend(); });
    }

private:
    void init() override {
        sea_.init(program_factory());
        sky_ = std::make_unique<step06::Sky>(program_factory(), 128);
        renderer_.init(program_factory());
        post_.init(program_factory());
    }

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

    void render() override {
        post_.begin(framebuffer_size());
        const glm::mat4 view_projection = camera().projection(aspect()) * camera().view(sea_.world_origin());
        const step06::SeaFrame frame{view_projection, camera().eye_world(), framebuffer_size(),
                                     post_.scene_framebuffer(), post_.depth_texture(), fullscreen_vao()};
        {
            ocean::GpuScope timed(timers(), "ocean");
            renderer_.record(sea_, frame);
            shade_in_compute(frame);
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

    // A thread a pixel, 8 x 8 a workgroup; the pixels where the mesh drew nothing keep the
    // cleared scene, for the background to fill.
    void shade_in_compute(const step06::SeaFrame& frame) {
        if (renderer_.wireframe()) return;  // the wireframe is drawn straight into the scene
        ocean::ShaderProgram* shade =
            program("ocean_shade_compute", {"ocean_shade.comp"}, renderer_.shading_defines(sea_, look_));
        if (shade == nullptr) return;
        renderer_.bind_shading(*shade, sea_, *sky_, look_, frame);
        glBindTextureUnit(kDepthUnit, post_.depth_texture());
        glBindImageTexture(0, post_.scene_texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glUseProgram(shade->id());
        glDispatchCompute(GLuint((frame.size.x + 7) / 8), GLuint((frame.size.y + 7) / 8), 1);
        // What follows draws into the scene (the background) and reads it (bloom).
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    step06::Sea sea_;
    std::unique_ptr<step06::Sky> sky_;
    step06::SeaRenderer renderer_;
    step06::PostProcess post_;
    step06::LookParams look_;
};

}  // namespace

OCEAN_MAIN(ComputeShading)
