// step06's parameters for light, sky, water shading, fog, bloom and tonemapping, declared once,
// with the uniform upload that goes with them. Colours are picked in sRGB and used linear.
#pragma once

#include "common/params.hpp"
#include "common/shader.hpp"
#include "step03_lighting/light_params.hpp"
#include "step06_foam_sky/sky.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace step06 {

class LookParams {
public:
    void declare(ocean::ParamRegistry& p) {
        auto g = [](ocean::Param& param, const char* group) -> ocean::Param& { return param.in_group(group); };
        g(p.add_float("sun_azimuth", &sun_azimuth, 330, 0, 360, "sun heading, degrees (0 = +x, 90 = +z)"), "sun and sky");
        g(p.add_float("sun_elevation", &sun_elevation, 18, -5, 90, "sun height above the horizon, degrees"), "sun and sky");
        g(p.add_float("sun_intensity", &sun_intensity, 6, 0, 100, "sunlight, linear units (the disc is brighter)"), "sun and sky");
        g(p.add_color("sun_colour", &sun_colour, {1.0f, 0.92f, 0.8f}, "colour of the sunlight (sRGB)"), "sun and sky");
        g(p.add_color("zenith_colour", &zenith_colour, {0.16f, 0.36f, 0.7f}, "sky straight up (sRGB)"), "sun and sky");
        g(p.add_color("horizon_colour", &horizon_colour, {0.6f, 0.7f, 0.8f}, "sky at the horizon (sRGB)"), "sun and sky");
        g(p.add_float("cloud_cover", &cloud_cover, 0.35f, 0, 1, "fraction of the sky under cloud"), "sun and sky");
        g(p.add_float("cloud_speed", &cloud_speed, 12, 0, 100, "cloud drift, metres per second"), "sun and sky");
        g(p.add_text("sky_image", &sky_image, "", "equirectangular sky image (.hdr, .png); empty: procedural"), "sun and sky");
        g(p.add_choice("microfacet", &microfacet, 0, {"ggx", "beckmann"}, "specular microfacet distribution"), "water");
        g(p.add_float("roughness", &roughness, 0.08f, 0.01f, 1, "microfacet roughness alpha near the camera"), "water");
        g(p.add_float("roughness_far", &roughness_far, 0.3f, 0.01f, 1, "roughness far away (unresolved waves)"), "water");
        g(p.add_float("roughness_distance", &roughness_distance, 400, 1, 10000, "metres over which roughness grows"), "water");
        g(p.add_color("scatter_colour", &scatter_colour, {0.05f, 0.32f, 0.36f}, "colour of light scattered in the water (sRGB)"), "water");
        g(p.add_color("bubble_colour", &bubble_colour, {0.2f, 0.45f, 0.45f}, "colour of light scattered by bubbles (sRGB)"), "water");
        g(p.add_float("scatter_crest", &k1, 1.2f, 0, 10, "k1: light through the crests (times wave height)"), "water");
        g(p.add_float("scatter_view", &k2, 0.35f, 0, 10, "k2: scatter towards the viewer"), "water");
        g(p.add_float("scatter_lambert", &k3, 0.25f, 0, 10, "k3: Lambert term of the scattered light"), "water");
        g(p.add_float("scatter_bubbles", &k4, 0.3f, 0, 10, "k4: bubbles (where there is foam)"), "water");
        g(p.add_float("height_scale", &height_scale, 2.0f, 0.01f, 50, "metres of height that count as a full crest"), "water");
        g(p.add_float("ambient", &ambient, 0.6f, 0, 10, "skylight reaching the water, linear"), "water");
        g(p.add_color("foam_colour", &foam_colour, {0.92f, 0.94f, 0.95f}, "foam albedo (sRGB)"), "water");
        g(p.add_float("foam_roughness", &foam_roughness, 0.6f, 0.01f, 1, "microfacet roughness of foam"), "water");
        g(p.add_float("fog_density", &fog_density, 0.0012f, 0, 0.1f, "fog per metre at sea level"), "post");
        g(p.add_float("fog_falloff", &fog_falloff, 0.02f, 0.0001f, 1, "how fast fog thins with height, per metre"), "post");
        g(p.add_float("bloom_threshold", &bloom_threshold, 2.5f, 0, 100, "linear brightness where bloom starts"), "post");
        g(p.add_float("bloom_strength", &bloom_strength, 0.06f, 0, 2, "how much of the glow is added"), "post");
        g(p.add_float("exposure", &exposure, 0.9f, 0.01f, 20, "scale before the tonemapper"), "post").logarithmic();
        g(p.add_choice("tonemapper", &tonemapper, 0, {"aces", "agx", "none"}, "filmic curve: ACES fitted, AgX, or a clamp"), "post");
        for (std::size_t i = 0; i < std::size(kToggles); ++i)
            g(p.add_bool(std::string("show_") + kToggles[i], &shown[i], true, std::string("draw the ") + kToggles[i]),
              "terms and passes");
    }

    glm::vec3 to_sun() const {
        const auto d = step03::sun_direction(sun_azimuth, sun_elevation);
        return {float(d.x), float(d.y), float(d.z)};
    }
    glm::vec3 sun_radiance() const { return sun_intensity * step03::srgb_to_linear(sun_colour); }

    // The clouds drift with the wind that raises the sea (wind_direction_deg: where it blows to).
    SkySettings sky(double time, double wind_direction_deg) const {
        SkySettings s;
        s.to_sun = to_sun();
        s.sun_radiance = s.sun_disc_gain * sun_radiance();  // the disc outshines the light it casts
        s.zenith = step03::srgb_to_linear(zenith_colour);
        s.horizon = step03::srgb_to_linear(horizon_colour);
        s.cloud_cover = cloud_cover;
        // sky.glsl samples the cloud pattern at (position + offset): an offset of -d t moves the
        // pattern along +d. Wrapped at 100 km (the noise is not periodic, but a jump once per
        // hours of drift goes unseen).
        const double wind = wind_direction_deg * 3.14159265358979323846 / 180.0;
        const double drift = std::fmod(time * cloud_speed, 1.0e5);
        s.cloud_offset = -glm::vec2(float(drift * std::cos(wind)), float(drift * std::sin(wind)));
        return s;
    }

    void upload_shading(const ocean::ShaderProgram& p) const {
        p.set("u_to_sun", to_sun());
        p.set("u_sun_radiance", sun_radiance());
        p.set("u_ambient", ambient * step03::srgb_to_linear(glm::mix(horizon_colour, zenith_colour, 0.5f)));
        p.set("u_roughness", roughness);
        p.set("u_roughness_far", roughness_far);
        p.set("u_roughness_distance", roughness_distance);
        p.set("u_height_scale", height_scale);
        p.set("u_scatter_colour", step03::srgb_to_linear(scatter_colour));
        p.set("u_bubble_colour", step03::srgb_to_linear(bubble_colour));
        p.set("u_foam_colour", step03::srgb_to_linear(foam_colour));
        p.set("u_k1", k1);
        p.set("u_k2", k2);
        p.set("u_k3", k3);
        p.set("u_k4", k4);
        p.set("u_foam_roughness", foam_roughness);
        p.set("u_fog_density", fog_density);
        p.set("u_fog_falloff", fog_falloff);
        p.set("u_show_ambient", int(show("ambient_term")));
        p.set("u_show_scatter", int(show("scatter_term")));
        p.set("u_show_specular", int(show("specular_term")));
        p.set("u_show_reflection", int(show("reflection_term")));
        p.set("u_show_foam", int(show("foam")));
        p.set("u_show_fog", int(show("fog")));
    }

    bool show(const char* name) const { return shown[index(name)]; }

    float sun_azimuth = 330, sun_elevation = 18, sun_intensity = 6, cloud_cover = 0.35f, cloud_speed = 12;
    glm::vec3 sun_colour{1.0f}, zenith_colour{0.0f}, horizon_colour{0.0f};
    std::string sky_image;
    int microfacet = 0, tonemapper = 0;
    float roughness = 0.08f, roughness_far = 0.3f, roughness_distance = 400;
    glm::vec3 scatter_colour{0.0f}, bubble_colour{0.0f}, foam_colour{1.0f};
    float k1 = 1.2f, k2 = 0.35f, k3 = 0.25f, k4 = 0.3f, height_scale = 2, ambient = 0.6f, foam_roughness = 0.6f;
    float fog_density = 0.0012f, fog_falloff = 0.02f, bloom_threshold = 2.5f, bloom_strength = 0.06f, exposure = 0.9f;

private:
    // What show_<name> turns on and off: each lighting term and each pass.
    static constexpr const char* kToggles[] = {"ambient_term", "scatter_term", "specular_term", "reflection_term",
                                               "foam", "fog", "bloom"};
    static std::size_t index(const std::string& name) {
        for (std::size_t i = 0; i < std::size(kToggles); ++i)
            if (name == kToggles[i]) return i;
        return 0;
    }
    bool shown[std::size(kToggles)] = {true, true, true, true, true, true, true};
};

}  // namespace step06
