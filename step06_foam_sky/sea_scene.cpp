#include "step06_foam_sky/sea_scene.hpp"

namespace step06 {

void SeaScene::declare(ocean::ParamRegistry& p) {
    sea_.declare(p);
    renderer_.declare(p);
    look_.declare(p);
}

void SeaScene::init(const ocean::ProgramFactory& programs) {
    sea_.init(programs);
    sky_ = std::make_unique<Sky>(programs, 128);
    renderer_.init(programs);
    post_.init(programs);
}

// Each GpuScope times the pass inside its braces for --bench, under the name frame_passes.hpp
// gives it.
void SeaScene::update(double time, double dt, const ocean::Camera& camera, ocean::GpuTimers& timers) {
    const glm::dvec3 eye = camera.eye_world();
    {
        ocean::GpuScope timed(timers, "simulation");
        sea_.simulate(time, eye);
    }
    {
        ocean::GpuScope timed(timers, "foam");
        sea_.update_foam(dt, eye, camera.forward());
    }
    ocean::GpuScope timed(timers, "sky");
    sky_->update(look_.sky(time, sea_.wind_direction()), look_.sky_image, look_.sky_image_changes.value);
}

// Camera-relative: the view, the mesh and the shading work in metres from the sea's world origin
// near the camera, so their float positions stay small anywhere on the ocean.
void SeaScene::render(const SceneView& view, ocean::GpuTimers& timers, const FrameAdditions& additions) {
    post_.begin(view.size);
    const glm::mat4 view_projection = view.camera.projection(view.aspect) * view.camera.view(sea_.world_origin());
    const SeaFrame frame{view_projection, view.camera.eye_world(), view.size, post_.scene_framebuffer(),
                         post_.depth_texture(), view.fullscreen_vao};
    {
        ocean::GpuScope timed(timers, "ocean");
        if (!additions.shade_sea) {
            renderer_.draw(sea_, *sky_, look_, frame);
        } else {
            renderer_.record(sea_, frame);
            if (!renderer_.wireframe()) additions.shade_sea(frame);
        }
    }
    if (additions.draw_into_scene) additions.draw_into_scene(view_projection);
    {
        ocean::GpuScope timed(timers, "background");
        sky_->draw_background(view_projection, view.fullscreen_vao);
    }
    const PostSettings image = look_.post(renderer_.view() == kViewShaded);
    {
        ocean::GpuScope timed(timers, "bloom");
        post_.bloom(image, view.fullscreen_vao);
    }
    ocean::GpuScope timed(timers, "tonemap");
    view.bind_screen();
    post_.tonemap(image, view.fullscreen_vao);
}

}  // namespace step06
