// step06's frame as one part: the program's four parts (the Sea, the Sky, the SeaRenderer, the
// PostProcess) and the parameters they share (LookParams), run in the order a frame runs them.
// main.cpp owns a SeaScene and calls update() and render() once a frame each. A program that
// draws more into the scene (things afloat), or shades the sea its own way, owns one too and
// gives render() what it adds (FrameAdditions); the parts stay reachable for what it asks of them.
#pragma once

#include "common/camera.hpp"
#include "common/gpu_timer.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/sea_renderer.hpp"
#include "step06_foam_sky/sky.hpp"

#include <glm/mat4x4.hpp>

#include <functional>
#include <memory>

namespace step06 {

// What the program lends a frame: its camera, and its framebuffer (the size, the aspect and how
// to bind it: App::bind_target), where the tonemapper writes the finished picture.
struct SceneView {
    const ocean::Camera& camera;
    glm::ivec2 size;  // pixels
    float aspect;
    GLuint fullscreen_vao;
    std::function<void()> bind_screen;
};

// What a program adds to the frame; each is optional.
struct FrameAdditions {
    // Drawn into the HDR scene after the sea, whose depth is there to hide what is under the
    // water, and before the sky fills what the sea left. Given the view-projection from the sea's
    // world origin (Sea::world_origin), as the sea is drawn.
    std::function<void(const glm::mat4& view_projection)> draw_into_scene;
    // The sea's pixels shaded another way: called once the mesh has recorded the G-buffer
    // (SeaRenderer::record), in place of SeaRenderer::draw's full-screen pass. Not called for the
    // wireframe, which record() draws straight into the scene.
    std::function<void(const SeaFrame& frame)> shade_sea;
};

class SeaScene {
public:
    // The parameters, in the order a frame uses them: the sea (spectrum, cascades, foam), the mesh
    // and the view, then the sky, the water's light and the image passes.
    void declare(ocean::ParamRegistry& p);
    void init(const ocean::ProgramFactory& programs);

    // Once a frame, before render(): the sea, its foam and the sky move on.
    void update(double time, double dt, const ocean::Camera& camera, ocean::GpuTimers& timers);
    // The sea into the HDR scene, the sky behind it, then bloom and the tonemapper to the screen.
    void render(const SceneView& view, ocean::GpuTimers& timers, const FrameAdditions& additions = {});

    Sea& sea() { return sea_; }
    const Sea& sea() const { return sea_; }
    const Sky& sky() const { return *sky_; }  // from init() on
    const SeaRenderer& renderer() const { return renderer_; }
    const PostProcess& post() const { return post_; }
    const LookParams& look() const { return look_; }

private:
    Sea sea_;
    std::unique_ptr<Sky> sky_;
    SeaRenderer renderer_;
    PostProcess post_;
    LookParams look_;
};

}  // namespace step06
