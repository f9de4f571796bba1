// Chapter 8's laboratory view: the wake alone, seen from above (the `plan` parameter). A boat
// sails at a set speed on still water (wake_scene.hpp) and the field's heights are drawn as a
// hill-shaded map (shaders/wake.frag), with Kelvin's edges if asked: the picture of sections 1 to
// 5 of the lesson, where nothing but the wake moves.
#pragma once

#include "common/gl_texture.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step08_wakes/wake_scene.hpp"

#include <glm/vec2.hpp>

#include <memory>
#include <vector>

namespace step08 {

class PlanView {
public:
    // Its own parameters (the boat's speed, draft and rudder, the shading's relief, Kelvin's lines,
    // the grid's outline); the boat's length is the program's (step07's boat_length).
    void declare(ocean::ParamRegistry& p);
    // Builds the view's program at once, whichever view is shown: a shader broken by an edit is
    // reported when the program starts, not when the view is first chosen.
    void init(ocean::ProgramFactory programs);

    // A new scene when the field's settings change (sailing `warm_up` seconds first, so the view
    // opens on a wake), then `dt` seconds of sailing, the rudder plus `extra_rudder` (the arrows).
    void update(double dt, const WaveFieldSettings& field, double boat_length, double warm_up, double extra_rudder);
    // A stone of `impulse` m^4/s at the world point (x, z) (outside the grid it pushes on nothing).
    void drop_stone(glm::dvec2 at, double impulse);

    // The view, `aspect` wide for 1 high, into the bound framebuffer.
    void draw(float aspect, int pixels_high, GLuint fullscreen_vao);
    // A point of the picture (u, v from 0 to 1, v up) to the world point under it (x, z).
    glm::dvec2 to_world(glm::dvec2 uv, float aspect) const;

    const WakeScene* scene() const { return scene_.get(); }
    const BoatSettings& boat() const { return boat_; }
    double rudder() const { return rudder_; }

private:
    ocean::ShaderProgram* program() const;
    glm::dvec2 view_centre() const;
    glm::dvec2 half_view(float aspect) const;  // the grid's side fills the picture's height

    ocean::ProgramFactory programs_;
    BoatSettings boat_;
    float rudder_ = 0, relief_ = 8;
    bool show_field_ = false, kelvin_lines_ = false;
    std::unique_ptr<WakeScene> scene_;
    ocean::Texture heights_;
    int texture_cells_ = 0;
    std::vector<float> upload_;
};

}  // namespace step08
