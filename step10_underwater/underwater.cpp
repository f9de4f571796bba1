#include "step10_underwater/underwater.hpp"

#include "common/gl_texture.hpp"
#include "step03_lighting/light_params.hpp"
#include "step06_foam_sky/far_plane.hpp"
#include "step06_foam_sky/texture_units.h"
#include "step10_underwater/optics.hpp"
#include "step10_underwater/underwater_units.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace step10 {

void Underwater::declare(ocean::ParamRegistry& p) {
    const auto group = p.group("underwater");
    std::vector<std::string> names;
    for (const WaterType& w : kWaterTypes) names.emplace_back(w.name);
    p.add_choice("water_type", &water_type_, names, "the water: its absorption and scattering per colour");
    p.add_float("seabed_depth", &seabed_depth_, 1, 200, "metres from the mean level down to the sand").logarithmic();
    p.add_color("seabed_colour", &seabed_colour_, "the sand's colour (sRGB)");
    p.add_bool("show_caustics", &show_caustics_, "the sunlight the waves focus on the seabed");
    p.add_float("caustic_size", &caustic_size_, 8, 200, "metres of seabed the caustics are computed over, around the camera");
}

void Underwater::init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }

WaterLight Underwater::light(const step06::LookParams& look) const {
    return water_light(water(), seabed_depth_, glm::dvec3(step03::srgb_to_linear(seabed_colour_)), look);
}

void Underwater::bind_water(const ocean::ShaderProgram& p, const step06::SeaScene& scene) const {
    const WaterLight w = light(scene.look());
    p.set("u_absorption", glm::vec3(w.absorption));
    p.set("u_water_scattering", glm::vec3(w.water_scattering));
    p.set("u_particle_scattering", glm::vec3(w.particle_scattering));
    p.set("u_particle_g", float(w.particle_g));
    p.set("u_seabed_depth", float(w.seabed_depth));
    p.set("u_seabed_albedo", glm::vec3(w.seabed_albedo));
    p.set("u_sun_in_water", glm::vec3(w.sun_in_water));
    p.set("u_sun_beam", glm::vec3(w.sun_beam));
    p.set("u_sky_down", glm::vec3(w.sky_down));
    p.set("u_caustic_centre", caustic_centre_);
    p.set("u_caustic_size", caustic_size_);
    p.set("u_show_caustics", int(show_caustics_ && !caustics_failed_ && caustics_.id() != 0));
    ocean::bind_texture(UNIT_CAUSTICS, GL_TEXTURE_2D, caustics_.id());
}

void Underwater::make_grid() {
    std::vector<GLuint> indices;
    indices.reserve(std::size_t(grid_side_ - 1) * (grid_side_ - 1) * 6);
    for (int j = 0; j + 1 < grid_side_; ++j)
        for (int i = 0; i + 1 < grid_side_; ++i) {
            const GLuint a = GLuint(j * grid_side_ + i), b = a + 1, c = a + GLuint(grid_side_), d = c + 1;
            indices.insert(indices.end(), {a, b, c, b, d, c});
        }
    grid_indices_ = ocean::make_buffer();
    grid_vao_ = ocean::make_vertex_array();
    // Made indices before they hold data (WebGL fixes a buffer's kind at its first binding).
    ocean::element_buffer(grid_vao_, grid_indices_);
    ocean::buffer_data(grid_indices_, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(), GL_STATIC_DRAW);
    grid_index_count_ = GLsizei(indices.size());
    grid_made_for_ = grid_side_;
}

void Underwater::update_caustics(const step06::SeaScene& scene, const glm::vec3& eye, ocean::GpuTimers& timers) {
    if (!show_caustics_ || caustics_failed_) return;
    ocean::GpuScope timed(timers, "caustics");
    if (caustics_.id() == 0) {
        caustics_ = ocean::make_float_texture_2d(GL_RGBA16F, caustic_resolution_, caustic_resolution_);
        caustic_target_ = ocean::make_framebuffer();
        if (!ocean::attach_texture_2d(caustic_target_, GL_COLOR_ATTACHMENT0, caustics_)) {
            // A GL that cannot draw into half floats: the seabed is lit evenly, as under a flat sea.
            std::cerr << "warning: this GL cannot draw into an RGBA16F texture: the seabed is drawn without caustics"
                      << std::endl;
            caustics_failed_ = true;
            caustics_.reset();
            return;
        }
    }
    if (grid_made_for_ != grid_side_) make_grid();
    // The window follows the camera in whole texels, so the pattern does not swim as it moves.
    const float texel = caustic_size_ / float(caustic_resolution_);
    caustic_centre_ = glm::vec2(std::round(eye.x / texel), std::round(eye.z / texel)) * texel;
    // The rays start over a margin of the window: light that the waves bend in from outside it.
    const float step = caustic_size_ / float(grid_side_ - 1) * 1.25f;
    const glm::vec2 origin = caustic_centre_ - 0.5f * step * float(grid_side_ - 1);

    const step06::SeaRenderer& renderer = scene.renderer();
    ocean::ShaderProgram* p = programs_("caustics", {"step10_underwater/shaders/caustics.vert",
                                                     "step10_underwater/shaders/caustics.frag"},
                                        renderer.shading_defines(scene.sea(), scene.look()));
    if (p == nullptr) return;
    ocean::OffscreenPassState pass(grid_vao_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, caustic_target_.id());
    glViewport(0, 0, caustic_resolution_, caustic_resolution_);
    const float clear[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    scene.sea().bind_maps(*p);
    glUseProgram(p->id());
    const glm::vec3 to_sun = glm::normalize(scene.look().to_sun());
    p->set("u_grid_origin", origin);
    p->set("u_grid_step", step);
    p->set("u_grid_side", grid_side_);
    p->set("u_sun_in_air", -to_sun);
    p->set("u_seabed_depth", seabed_depth_);
    p->set("u_caustic_centre", caustic_centre_);
    p->set("u_caustic_size", caustic_size_);
    p->set("u_flat_transmitted", float(1 - fresnel_reflectance(std::acos(std::max(to_sun.y, 0.0f)), 1.0, kWaterIndex)));
    glDrawElements(GL_TRIANGLES, grid_index_count_, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_BLEND);
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
