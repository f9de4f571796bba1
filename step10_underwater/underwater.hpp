// The sea from below, the chapter's one new part. While the camera is under the mean level it
// takes over step06's frame at two points (step06::FrameAdditions): the sea's pixels are shaded as
// seen from the water (underwater_shade.frag: Snell's window, Fresnel from below, the depths
// mirrored past the critical angle), and every other pixel is the water itself or the seabed
// (underwater_fill.frag), lit through caustics the waves focus (caustics.vert/.frag, drawn into a
// texture of the seabed under the camera before the frame).
#pragma once

#include "common/gl.hpp"
#include "common/gpu_timer.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/sea_scene.hpp"
#include "step10_underwater/caustics.hpp"
#include "step10_underwater/water_colour.hpp"
#include "step10_underwater/water_light.hpp"

#include <glm/vec3.hpp>

namespace step10 {

// Gives a program that includes water.glsl the water `w` describes (its uniforms, by name).
void set_water(const ocean::ShaderProgram& p, const WaterLight& w);

class Underwater {
public:
    void declare(ocean::ParamRegistry& p);
    void init(ocean::ProgramFactory programs);
    // Before the frame, below the surface: the seabed's caustics under the camera (eye: metres from
    // the sea's world origin).
    void update_caustics(const step06::SeaScene& scene, const glm::vec3& eye, ocean::GpuTimers& timers);
    // What the frame adds below the surface: the sea shaded from below, and the water around it.
    step06::FrameAdditions additions(const step06::SeaScene& scene, const glm::vec3& eye, GLuint fullscreen_vao);

    const WaterType& water() const { return kWaterTypes[std::size_t(water_type_)]; }
    float seabed_depth() const { return seabed_depth_; }
    // The water the shaders are given (water_light.hpp), under `look`'s sun and sky.
    WaterLight light(const step06::LookParams& look) const;

private:
    void bind_water(const ocean::ShaderProgram& p, const step06::SeaScene& scene) const;

    ocean::ProgramFactory programs_;
    int water_type_ = 0;
    float seabed_depth_ = 12;
    glm::vec3 seabed_colour_{0.76f, 0.70f, 0.50f};  // sand (sRGB)
    bool show_caustics_ = true;
    float below_exposure_ = 2.2f;  // a stop more than above: 2 over step06's 0.9, as the water was first shown
    CausticWindow caustic_window_;  // 32 m of seabed, 16 cm texels, rays as far apart
    Caustics caustics_;
};

}  // namespace step10
