// The parameters of chapter 2's light, declared once for every program that uses it (step03's,
// and any that lights another sea the same way).
#pragma once

#include "common/params.hpp"
#include "step03_lighting/lighting.hpp"

#include <glm/vec3.hpp>

#include <cmath>

namespace step03 {

// Colour pickers show sRGB; the lighting adds linear light.
inline glm::vec3 srgb_to_linear(glm::vec3 c) {
    for (int i = 0; i < 3; ++i)
        c[i] = c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
    return c;
}

class LightParams {
public:
    void declare(ocean::ParamRegistry& p) {
        p.add_float("sun_azimuth", &sun_azimuth_, 0, 360, "sun heading, degrees (0 = +x, 90 = +z)")
            .in_group("light");
        p.add_float("sun_elevation", &sun_elevation_, -10, 90, "sun height above the horizon, degrees")
            .in_group("light");
        p.add_color("sun_colour", &sun_colour_, "colour of the sunlight (sRGB)")
            .in_group("light");
        p.add_color("water_colour", &water_colour_, "diffuse tint of the water (sRGB)")
            .in_group("light");
        p.add_color("ambient_colour", &ambient_colour_, "light from the whole sky (sRGB)")
            .in_group("light");
        p.add_float("shininess", &shininess_, 1, 4096, "Blinn-Phong exponent: larger, smaller highlight")
            .in_group("light").logarithmic();
    }

    Light light() const {
        auto colour = [](glm::vec3 srgb) {
            const glm::vec3 c = srgb_to_linear(srgb);
            return Colour{c.r, c.g, c.b};
        };
        return {sun_direction(sun_azimuth_, sun_elevation_), colour(sun_colour_), colour(water_colour_),
                colour(ambient_colour_), shininess_};
    }

    // The sky colour the sea fades into with distance (linear), and as the clear colour (sRGB).
    static glm::vec3 background_srgb() { return {0.55f, 0.66f, 0.76f}; }

private:
    float sun_azimuth_ = 305, sun_elevation_ = 25, shininess_ = 160;
    glm::vec3 sun_colour_{1.0f, 0.96f, 0.88f}, water_colour_{0.10f, 0.42f, 0.66f}, ambient_colour_{0.04f, 0.14f, 0.24f};
};

}  // namespace step03
