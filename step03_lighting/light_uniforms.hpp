// Hands chapter 2's light to lighting.glsl. Shared by the step and the GPU read-back test.
#pragma once

#include "common/shader.hpp"
#include "step03_lighting/lighting.hpp"

namespace step03 {

inline glm::vec3 to_vec3(const Colour& c) { return {float(c.r), float(c.g), float(c.b)}; }

inline void upload_light(const ocean::ShaderProgram& program, const Light& light) {
    program.set("u_to_sun", glm::vec3(float(light.to_sun.x), float(light.to_sun.y), float(light.to_sun.z)));
    program.set("u_sun_color", to_vec3(light.sun));
    program.set("u_water_color", to_vec3(light.water));
    program.set("u_ambient_color", to_vec3(light.ambient));
    program.set("u_shininess", float(light.shininess));
}

}  // namespace step03
