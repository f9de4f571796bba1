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
// The program is step06's frame (its SeaScene, sea_scene.hpp) with one pass changed: the mesh
// still records the G-buffer (SeaRenderer::record), then shaders/ocean_shade.comp shades it with
// step06's own shading (ocean_shade.glsl) and the same inputs (SeaRenderer::bind_shading), given
// to the frame as its shade_sea.
#include "common/app.hpp"
#include "step06_foam_sky/sea_scene.hpp"

namespace {

// The scene's depth for ocean_shade.comp (UNIT_GBUFFER_DEPTH there): a unit step06's table
// (texture_units.h) leaves free.
constexpr GLuint kDepthUnit = 8;

class ComputeShading : public ocean::App {
public:
    ComputeShading()
        : App({"step06 with compute shading", "", "step06's frame with its shading pass as a compute shader.",
               /*window_samples=*/0}) {
        scene_.declare(params());
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_bench_figures([this] { return scene_.sea().time_backends(time()); });
        offer_warm_up([this] { return scene_.sea().choosing_backend(); });
    }

private:
    void init() override { scene_.init(program_factory()); }

    void update(double time, double dt) override { scene_.update(time, dt, camera(), timers()); }

    void render() override {
        step06::FrameAdditions additions;
        additions.shade_sea = [this](const step06::SeaFrame& frame) { shade_in_compute(frame); };
        scene_.render({camera(), framebuffer_size(), aspect(), fullscreen_vao(), [this] { bind_target(); }},
                      timers(), additions);
    }

    // A thread a pixel, 8 x 8 a workgroup; the pixels where the mesh drew nothing keep the
    // cleared scene, for the background to fill.
    void shade_in_compute(const step06::SeaFrame& frame) {
        const step06::SeaRenderer& renderer = scene_.renderer();
        ocean::ShaderProgram* shade = program("ocean_shade_compute", {"ocean_shade.comp"},
                                              renderer.shading_defines(scene_.sea(), scene_.look()));
        if (shade == nullptr) return;
        renderer.bind_shading(*shade, scene_.sea(), scene_.sky(), scene_.look(), frame);
        glBindTextureUnit(kDepthUnit, scene_.post().depth_texture());
        glBindImageTexture(0, scene_.post().scene_texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glUseProgram(shade->id());
        glDispatchCompute(GLuint((frame.size.x + 7) / 8), GLuint((frame.size.y + 7) / 8), 1);
        // What follows draws into the scene (the background) and reads it (bloom).
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    step06::SeaScene scene_;
};

}  // namespace

OCEAN_MAIN(ComputeShading)
