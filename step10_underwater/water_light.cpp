#include "step10_underwater/water_light.hpp"

#include "common/constants.hpp"
#include "step03_lighting/light_params.hpp"
#include "step10_underwater/optics.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace step10 {

WaterLight water_light(const WaterType& water, double seabed_depth, const glm::dvec3& seabed_albedo,
                       const step06::LookParams& look) {
    WaterLight w;
    w.absorption = absorption(water);
    w.water_scattering = pure_water_scattering();
    w.particle_scattering = water.particle_scattering;
    w.particle_g = water.particle_g;
    w.seabed_depth = seabed_depth;
    w.seabed_albedo = seabed_albedo;
    const glm::dvec3 to_sun = glm::normalize(glm::dvec3(look.to_sun()));
    const auto refracted = refract_air_to_water(-to_sun, {0, 1, 0});
    w.sun_in_water = refracted ? *refracted : glm::dvec3(0, -1, 0);
    // Through a level plane: the beam's irradiance times cos_air, of which T crosses; across the
    // refracted beam, that over cos_water.
    const double cos_air = std::max(to_sun.y, 0.0), cos_water = std::max(-w.sun_in_water.y, 1e-3);
    const double transmitted = 1 - fresnel_reflectance(std::acos(cos_air), 1.0, kWaterIndex);
    w.sun_beam = glm::dvec3(look.sun_radiance()) * (cos_air * transmitted / cos_water);
    // The sky's light on a level plane, pi times its mean radiance, of which about 93 % crosses (a
    // diffuse sky's mean transmittance into water).
    const glm::dvec3 sky(step03::srgb_to_linear(glm::mix(look.horizon_colour, look.zenith_colour, 0.5f)));
    w.sky_down = double(look.ambient) * ocean::kPi * 0.93 * sky;
    return w;
}

glm::dvec3 phase(const WaterLight& w, double cos_theta) {
    return (w.water_scattering * water_phase(cos_theta) +
            w.particle_scattering * henyey_greenstein_phase(cos_theta, w.particle_g)) /
           w.scattering();
}

glm::dvec3 beam_inscatter(const WaterLight& w, double z_eye, const glm::dvec3& d, double t, const glm::dvec3& beam,
                          const glm::dvec3& across, const glm::dvec3& p) {
    const glm::dvec3 c = w.extinction();
    const double mu = std::max(-beam.y, 1e-3);
    const glm::dvec3 k = c * (1.0 - d.y / mu);
    glm::dvec3 along(t);  // k -> 0: the integral is t
    for (int i = 0; i < 3; ++i)
        if (std::abs(k[i]) * t > 1e-4) along[i] = (1 - std::exp(-k[i] * t)) / k[i];
    return w.scattering() * p * across * glm::exp(-c * z_eye / mu) * along;
}

glm::dvec3 inscatter(const WaterLight& w, double z_eye, const glm::dvec3& d, double t) {
    return beam_inscatter(w, z_eye, d, t, w.sun_in_water, w.sun_beam, phase(w, glm::dot(w.sun_in_water, -d))) +
           beam_inscatter(w, z_eye, d, t, {0, -1, 0}, w.sky_down, glm::dvec3(1 / (4 * ocean::kPi)));
}

glm::dvec3 seabed_radiance(const WaterLight& w, double caustic) {
    const glm::dvec3 c = w.extinction();
    const double mu = std::max(-w.sun_in_water.y, 1e-3);
    const glm::dvec3 sun = w.sun_beam * mu * glm::exp(-c * w.seabed_depth / mu) * caustic;
    const glm::dvec3 sky = w.sky_down * glm::exp(-c * w.seabed_depth);
    return w.seabed_albedo / ocean::kPi * (sun + sky);
}

glm::dvec3 seabed_seen(const WaterLight& w, double z_eye, const glm::dvec3& d, double caustic) {
    const double t = (w.seabed_depth - z_eye) / -d.y;
    return seabed_radiance(w, caustic) * glm::exp(-w.extinction() * t) + inscatter(w, z_eye, d, t);
}

}  // namespace step10
