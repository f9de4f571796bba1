#include "step10_underwater/caustics.hpp"

#include "common/gl_texture.hpp"
#include "step10_underwater/optics.hpp"
#include "step10_underwater/underwater_units.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace step10 {

// A GL that cannot draw into float textures (ES without EXT_color_buffer_float): the seabed is
// lit evenly, as under a flat sea.
bool Caustics::cannot_draw() {
    std::cerr << "warning: this GL cannot draw into float textures: the seabed is drawn without caustics" << std::endl;
    failed_ = true;
    texture_.reset();
    return false;
}

bool Caustics::make_texture(int resolution) {
    texture_ = ocean::make_float_texture_2d(GL_RGBA16F, resolution, resolution);
    target_ = ocean::make_framebuffer();
    if (!ocean::attach_texture_2d(target_, GL_COLOR_ATTACHMENT0, texture_)) return cannot_draw();
    texture_resolution_ = resolution;
    return true;
}

// The rays' textures, and the two triangles between each four neighbouring rays: a vertex is a
// ray, read from the textures by gl_VertexID, so the grid is indices alone.
bool Caustics::make_grid(int rays) {
    rays_ = ocean::make_float_texture_2d(GL_RGBA32F, rays, rays);
    transmitted_ = ocean::make_float_texture_2d(GL_R32F, rays, rays);
    rays_target_ = ocean::make_framebuffer();
    if (!ocean::attach_texture_2d(rays_target_, GL_COLOR_ATTACHMENT0, rays_) ||
        !ocean::attach_texture_2d(rays_target_, GL_COLOR_ATTACHMENT1, transmitted_))
        return cannot_draw();
    const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    ocean::draw_buffers(rays_target_, 2, outputs);

    std::vector<GLuint> indices;
    indices.reserve(std::size_t(rays - 1) * std::size_t(rays - 1) * 6);
    for (int j = 0; j + 1 < rays; ++j)
        for (int i = 0; i + 1 < rays; ++i) {
            const GLuint a = GLuint(j * rays + i), b = a + 1, c = a + GLuint(rays), d = c + 1;
            indices.insert(indices.end(), {a, b, c, b, d, c});
        }
    grid_indices_ = ocean::make_buffer();
    grid_vao_ = ocean::make_vertex_array();
    // Made indices before they hold data (WebGL fixes a buffer's kind at its first binding).
    ocean::element_buffer(grid_vao_, grid_indices_);
    ocean::buffer_data(grid_indices_, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(), GL_STATIC_DRAW);
    grid_index_count_ = GLsizei(indices.size());
    grid_rays_ = rays;
    return true;
}

bool Caustics::update(const ocean::ProgramFactory& programs, const std::vector<std::string>& defines,
                      const BindSea& bind_sea, const CausticWindow& window, const CausticLight& light) {
    if (failed_) return false;
    if (texture_resolution_ != window.resolution && !make_texture(window.resolution)) return false;
    if (grid_rays_ != window.rays && !make_grid(window.rays)) return false;
    const std::string dir = "step10_underwater/shaders/";
    ocean::ShaderProgram* trace = programs("caustic_rays", {"common/shaders/fullscreen.vert", dir + "caustic_rays.frag"}, defines);
    ocean::ShaderProgram* triangles = programs("caustics", {dir + "caustics.vert", dir + "caustics.frag"}, {});
    ocean::ShaderProgram* points = programs("caustic_points", {dir + "caustic_points.vert", dir + "caustic_points.frag"}, {});
    if (trace == nullptr || triangles == nullptr || points == nullptr) return false;

    // The window follows the camera in whole texels, so the pattern does not swim as it moves.
    const float texel = window.size / float(window.resolution);
    centre_ = glm::vec2(std::round(light.around.x / texel), std::round(light.around.y / texel)) * texel;
    size_ = window.size;
    // The rays start over a margin of the window: light that the waves bend in from outside it.
    const float step = window.size / float(window.rays - 1) * 1.25f;
    const glm::vec2 origin = centre_ - 0.5f * step * float(window.rays - 1);
    const glm::vec3 to_sun = glm::normalize(light.to_sun);
    const float flat_transmitted = float(1 - fresnel_reflectance(std::acos(std::max(to_sun.y, 0.0f)), 1.0, kWaterIndex));

    ocean::OffscreenPassState pass(grid_vao_.id());
    // The rays, a texel each.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, rays_target_.id());
    glViewport(0, 0, window.rays, window.rays);
    bind_sea(*trace);
    glUseProgram(trace->id());
    trace->set("u_grid_origin", origin);
    trace->set("u_grid_step", step);
    trace->set("u_sun_in_air", -to_sun);
    trace->set("u_seabed_depth", light.seabed_depth);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Their light on the seabed, added up: the cells as triangles, then those too small as points.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_.id());
    glViewport(0, 0, window.resolution, window.resolution);
    const float clear[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    ocean::bind_texture(UNIT_CAUSTIC_RAYS, GL_TEXTURE_2D, rays_.id());
    ocean::bind_texture(UNIT_CAUSTIC_TRANSMITTED, GL_TEXTURE_2D, transmitted_.id());
    for (ocean::ShaderProgram* p : {triangles, points}) {
        p->set("u_grid_side", window.rays);
        p->set("u_caustic_centre", centre_);
        p->set("u_caustic_size", window.size);
        p->set("u_texel_area", texel * texel);
        p->set("u_flat_transmitted", flat_transmitted);
    }
    glUseProgram(triangles->id());
    glDrawElements(GL_TRIANGLES, grid_index_count_, GL_UNSIGNED_INT, nullptr);
#ifndef OCEAN_GL_ES  // ES always takes a point's size from gl_PointSize
    glEnable(GL_PROGRAM_POINT_SIZE);
#endif
    glUseProgram(points->id());
    glDrawArrays(GL_POINTS, 0, window.rays * window.rays);
#ifndef OCEAN_GL_ES
    glDisable(GL_PROGRAM_POINT_SIZE);
#endif
    glDisable(GL_BLEND);  // the pass state puts back only what was on before it
    return true;
}

}  // namespace step10
