// step06's parameters for light, sky, water shading, fog, bloom and tonemapping, declared once,
// with the uniform upload that goes with them. Colours are picked in sRGB and used linear.
#pragma once

#include "common/error.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step03_lighting/light_params.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/sky.hpp"

#include <glm/vec3.hpp>

#include <algorithm>

#include <string>

namespace step06 {

// Each effect step06 can leave out (show_<name>) or show beside its absence (split_effect),
// named once, here.
enum class Effect { AmbientTerm, ScatterTerm, SpecularTerm, ReflectionTerm, Foam, Fog, Bloom };
inline constexpr const char* kEffectNames[] = {"ambient_term", "scatter_term", "specular_term", "reflection_term",
                                               "foam", "fog", "bloom"};  // Effect's order
inline const char* effect_name(Effect e) { return kEffectNames[int(e)]; }
// The effect of that name; an unknown name is an error that lists the known ones.
inline Effect effect_named(const std::string& name) {
    std::string known;
    for (std::size_t i = 0; i < std::size(kEffectNames); ++i) {
        if (name == kEffectNames[i]) return Effect(i);
        known += (i ? ", " : "") + std::string(kEffectNames[i]);
    }
    throw ocean::Error("unknown effect '" + name + "' (" + known + ")");
}
// split_effect's choices, in the order its presets and --list-params have always had them.
inline constexpr Effect kSplitEffects[] = {Effect::Fog,          Effect::Bloom,          Effect::Foam,
                                           Effect::ScatterTerm,  Effect::SpecularTerm,   Effect::ReflectionTerm,
                                           Effect::AmbientTerm};

class LookParams {
public:
    // Every look parameter, declared once, in the order the panel and presets list them; the
    // member's initialiser (below) is its default.
    void declare(ocean::ParamRegistry& p) {
        {
            const auto sky_group = p.group(kSky);
            p.add_float("sun_azimuth", &sun_azimuth, 0, 360, "sun heading, degrees (0 = +x, 90 = +z)");
            p.add_float("sun_elevation", &sun_elevation, -5, 90, "sun height above the horizon, degrees");
            p.add_float("sun_intensity", &sun_intensity, 0, 100, "sunlight, linear units (the disc is brighter)");
            p.add_color("zenith_colour", &zenith_colour, "sky straight up (sRGB)");
            p.add_color("horizon_colour", &horizon_colour, "sky at the horizon (sRGB)");
            p.add_float("cloud_cover", &cloud_cover, 0, 1, "fraction of the sky under cloud");
            p.add_float("cloud_speed", &cloud_speed, 0, 100, "cloud drift, metres per second");
            p.add_text("sky_image", &sky_image, "equirectangular sky image (.hdr, .png); empty: procedural")
                .bumps(sky_image_changes);
        }
        {
            const auto water_group = p.group(kWater);
            p.add_choice("microfacet", &microfacet, {"ggx", "beckmann"}, "specular microfacet distribution");
            p.add_float("roughness", &roughness, 0.01f, 1, "a floor on alpha (the waves a pixel does not show add theirs)");
            p.add_color("scatter_colour", &scatter_colour, "colour of light scattered in the water (sRGB)");
            p.add_float("scatter_crest", &scatter_crest, 0, 10, "k1: sunlight through the crests (times wave height)");
        }
        {
            const auto post_group = p.group(kPost);
            p.add_float("fog_density", &fog_density, 0, 0.1f, "fog per metre at sea level");
            p.add_float("bloom_strength", &bloom_strength, 0, 2, "how much of the glow is added");
            p.add_float("exposure", &exposure, 0.01f, 20, "scale before the tonemapper").logarithmic();
            p.add_choice("tonemapper", &tonemapper, {"aces", "agx", "none"},
                         "filmic curve: ACES fitted or AgX (both dithered), or none: the values clamped as they are");
        }
        const auto effects_group = p.group("terms and passes");
        for (std::size_t i = 0; i < std::size(kEffectNames); ++i)
            p.add_bool(std::string("show_") + kEffectNames[i], &shown[i], std::string("draw the ") + kEffectNames[i]);
    }

    glm::vec3 to_sun() const {
        const auto d = step03::sun_direction(sun_azimuth, sun_elevation);
        return {float(d.x), float(d.y), float(d.z)};
    }
    // Direct sunlight after the clouds: broken cloud (cover up to a half) leaves the sun mostly
    // clear; towards overcast it dims to 15 % (a thick layer lets through about a tenth of the
    // direct beam). The glint, the scatter and the disc dim with it; the sky's own light stays.
    float sun_transmission() const {
        const float t = std::clamp((cloud_cover - 0.5f) / 0.5f, 0.0f, 1.0f);
        return 1.0f - 0.85f * t * t * (3.0f - 2.0f * t);
    }
    glm::vec3 sun_radiance() const { return sun_transmission() * sun_intensity * step03::srgb_to_linear(sun_colour); }

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
        p.set("u_height_scale", height_scale);
        p.set("u_scatter_colour", step03::srgb_to_linear(scatter_colour));
        p.set("u_bubble_colour", step03::srgb_to_linear(bubble_colour));
        p.set("u_crest_colour", step03::srgb_to_linear(crest_colour));
        p.set("u_foam_colour", step03::srgb_to_linear(foam_colour));
        p.set("u_scatter_crest", scatter_crest);
        p.set("u_scatter_view", scatter_view);
        p.set("u_scatter_lambert", scatter_lambert);
        p.set("u_scatter_bubbles", scatter_bubbles);
        p.set("u_foam_roughness", foam_roughness);
        p.set("u_fog_density", fog_density);
        p.set("u_fog_falloff", fog_falloff);
        p.set("u_show_ambient", int(show(Effect::AmbientTerm)));
        p.set("u_show_scatter", int(show(Effect::ScatterTerm)));
        p.set("u_show_specular", int(show(Effect::SpecularTerm)));
        p.set("u_show_reflection", int(show(Effect::ReflectionTerm)));
        p.set("u_show_foam", int(show(Effect::Foam)));
        p.set("u_show_fog", int(show(Effect::Fog)));
    }

    bool show(Effect e) const { return shown[std::size_t(e)]; }

    // The image passes this frame: the final picture as set, a debug view as it is.
    PostSettings post(bool final_picture) const {
        return {final_picture && show(Effect::Bloom), bloom_threshold, bloom_strength,
                final_picture ? exposure : 1.0f, final_picture ? tonemapper : kTonemapNone};
    }

    // The defaults (declare() binds each to its parameter; the others are the chapter's constants,
    // named in the lesson).
    float sun_azimuth = 330, sun_elevation = 11, sun_intensity = 6, cloud_cover = 0.35f, cloud_speed = 12;
    glm::vec3 sun_colour{1.0f, 0.92f, 0.8f}, zenith_colour{0.16f, 0.36f, 0.7f}, horizon_colour{0.6f, 0.7f, 0.8f};
    std::string sky_image;
    ocean::Generation sky_image_changes;  // bumped when sky_image changes: the image is loaded again
    int microfacet = 0, tonemapper = 0;
    float roughness = 0.02f;
    glm::vec3 scatter_colour{0.05f, 0.32f, 0.36f}, crest_colour{0.15f, 0.75f, 0.6f}, bubble_colour{0.2f, 0.45f, 0.45f}, foam_colour{0.92f, 0.94f, 0.95f};
    float scatter_crest = 3.0f, scatter_view = 0.35f, scatter_lambert = 0.25f, scatter_bubbles = 0.3f;  // the notes' k1 .. k4
    float height_scale = 2, ambient = 0.6f, foam_roughness = 0.6f;
    float fog_density = 0.0012f, fog_falloff = 0.02f, bloom_threshold = 2.5f, bloom_strength = 0.06f, exposure = 0.9f;

private:
    static constexpr const char* kSky = "sun and sky";
    static constexpr const char* kWater = "water";
    static constexpr const char* kPost = "post";
    bool shown[std::size(kEffectNames)] = {true, true, true, true, true, true, true};  // show_<effect>
};

}  // namespace step06
