#include "step10_underwater/underwater.hpp"

#include "common/gl_texture.hpp"
#include "step03_lighting/light_params.hpp"
#include "step06_foam_sky/far_plane.hpp"
#include "step06_foam_sky/texture_units.h"
#include "step10_underwater/underwater_units.h"

#include <glm/matrix.hpp>

#include <string>
#include <utility>
#include <vector>

namespace step10 {

void set_water(const ocean::ShaderProgram& p, const WaterLight& w) {
    p.set("u_absorption", glm::vec3(w.absorption));
    p.set("u_water_scattering", glm::vec3(w.water_scattering));
    p.set("u_particle_scattering", glm::vec3(w.particle_scattering));
    p.set("u_particle_g", float(w.particle_g));
    p.set("u_seabed_depth", float(w.seabed_depth));
    p.set("u_seabed_albedo", glm::vec3(w.seabed_albedo));
    p.set("u_sun_in_water", glm::vec3(w.sun_in_water));
    p.set("u_sun_beam", glm::vec3(w.sun_beam));
    p.set("u_sky_down", glm::vec3(w.sky_down));
}

void Underwater::declare(ocean::ParamRegistry& p) {
    const auto group = p.group("underwater");
    std::vector<std::string> names;
    for (const WaterType& w : kWaterTypes) names.emplace_back(w.name);
    p.add_choice("water_type", &water_type_, names, "the water: its absorption and scattering per colour");
    p.add_float("seabed_depth", &seabed_depth_, 1, 200, "metres from the mean level down to the sand").logarithmic();
    p.add_color("seabed_colour", &seabed_colour_, "the sand's colour (sRGB)");
    p.add_bool("show_caustics", &show_caustics_, "the sunlight the waves focus on the seabed");
    p.add_float("below_exposure", &below_exposure_, 0.1f, 20, "how much more the camera lets in below the surface")
        .logarithmic();
    p.add_float("caustic_size", &caustic_window_.size, 8, 200, "metres of seabed the caustics are computed over, around the camera");
}

void Underwater::init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }

WaterLight Underwater::light(const step06::LookParams& look) const {
    return water_light(water(), seabed_depth_, glm::dvec3(step03::srgb_to_linear(seabed_colour_)), look);
}

void Underwater::bind_water(const ocean::ShaderProgram& p, const step06::SeaScene& scene) const {
    set_water(p, light(scene.look()));
    p.set("u_below_exposure", below_exposure_);
    p.set("u_caustic_centre", caustics_.centre());
    p.set("u_caustic_size", caustics_.size());
    p.set("u_show_caustics", int(show_caustics_ && caustics_.texture() != 0 && !caustics_.failed()));
    ocean::bind_texture(UNIT_CAUSTICS, GL_TEXTURE_2D, caustics_.texture());
}

void Underwater::update_caustics(const step06::SeaScene& scene, const glm::vec3& eye, ocean::GpuTimers& timers) {
    if (!show_caustics_) return;
    ocean::GpuScope timed(timers, "caustics");
    const step06::Sea& sea = scene.sea();
    caustics_.update(programs_, sea.shader_defines(), [&sea](const ocean::ShaderProgram& p) { sea.bind_maps(p); },
                     caustic_window_, {scene.look().to_sun(), seabed_depth_, {eye.x, eye.z}});
}

step06::FrameAdditions Underwater::additions(const step06::SeaScene& scene, const glm::vec3& eye, GLuint fullscreen_vao) {
    step06::FrameAdditions a;
    const std::vector<std::string> defines = scene.renderer().shading_defines(scene.sea(), scene.look());
    a.shade_sea = [this, &scene, defines](const step06::SeaFrame& frame) {
        ocean::ShaderProgram* p = programs_("underwater_shade", {"fullscreen.vert", "step10_underwater/shaders/underwater_shade.frag"},
                                            defines);
        if (p == nullptr) return;
        scene.renderer().bind_shading(*p, scene.sea(), scene.sky(), scene.look(), frame);
        bind_water(*p, scene);
        glUseProgram(p->id());
        step06::draw_at_far_plane(GL_GREATER, frame.fullscreen_vao);
    };
    a.draw_into_scene = [this, &scene, eye, fullscreen_vao](const glm::mat4& view_projection) {
        ocean::ShaderProgram* p = programs_("underwater_fill", {"fullscreen.vert", "step10_underwater/shaders/underwater_fill.frag"}, {});
        if (p == nullptr) return;
        bind_water(*p, scene);
        p->set("u_inverse_view_projection", glm::inverse(view_projection));
        p->set("u_eye", eye);
        glUseProgram(p->id());
        // Just in front of the far plane, where the mesh left the depth cleared: the sky, drawn at
        // the far plane next, then finds these pixels taken.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthRangef(0.999999f, 0.999999f);
        glBindVertexArray(fullscreen_vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDepthRangef(0.0f, 1.0f);
        glDisable(GL_DEPTH_TEST);
    };
    return a;
}

}  // namespace step10
