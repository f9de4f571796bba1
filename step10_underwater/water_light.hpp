// The light in the water as the shaders compute it (shaders/water.glsl), in double: the CPU
// reference they are held to, and the one place the frame's water is described. WaterLight holds
// what the shaders receive as uniforms; the functions are water.glsl's, line for line.
#pragma once

#include "step06_foam_sky/look_params.hpp"
#include "step10_underwater/water_colour.hpp"

#include <glm/vec3.hpp>

namespace step10 {

struct WaterLight {
    glm::dvec3 absorption, water_scattering, particle_scattering;  // 1/m
    double particle_g = 0.9;
    double seabed_depth = 12;   // metres
    glm::dvec3 seabed_albedo{0.5};
    glm::dvec3 sun_in_water{0, -1, 0};  // the sun's beam below a flat surface: its direction (down)
    glm::dvec3 sun_beam{0};             // and irradiance across it
    glm::dvec3 sky_down{0};             // the sky's light through the surface, on a level plane

    glm::dvec3 scattering() const { return water_scattering + particle_scattering; }
    glm::dvec3 extinction() const { return absorption + scattering(); }
};

// The frame's water: `water`'s coefficients, the seabed, and the sun and sky of `look` crossing a
// flat surface (Fresnel in, refracted, the beam narrowed by the refraction).
WaterLight water_light(const WaterType& water, double seabed_depth, const glm::dvec3& seabed_albedo,
                       const step06::LookParams& look);

// water.glsl's functions: the phase of the mixture, one beam's light scattered towards an eye at
// depth z_eye looking along d over its first t metres, both beams', and the seabed's radiance.
glm::dvec3 phase(const WaterLight& w, double cos_theta);
glm::dvec3 beam_inscatter(const WaterLight& w, double z_eye, const glm::dvec3& d, double t, const glm::dvec3& beam,
                          const glm::dvec3& across, const glm::dvec3& p);
glm::dvec3 inscatter(const WaterLight& w, double z_eye, const glm::dvec3& d, double t);
glm::dvec3 seabed_radiance(const WaterLight& w, double caustic);

// What an eye at depth z_eye sees looking along d (downwards) at the seabed, with the caustics at
// `caustic` where it looks: the sand's light across the water, plus the water's own.
glm::dvec3 seabed_seen(const WaterLight& w, double z_eye, const glm::dvec3& d, double caustic);

}  // namespace step10
