#include "step10_underwater/waterline.hpp"

#include "common/gl_texture.hpp"
#include "step10_underwater/underwater_units.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace step10 {

namespace {

// The lens's lowest and highest points, metres above the mean level.
glm::dvec2 lens_heights(const ocean::Camera& camera, float aspect, const glm::dvec3& origin) {
    const glm::dmat4 to_world = glm::inverse(glm::dmat4(camera.projection(aspect)) * glm::dmat4(camera.view(origin)));
    glm::dvec2 heights(1e30, -1e30);
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0}) {
            const glm::dvec4 corner = to_world * glm::dvec4(x, y, -1, 1);  // on the near plane
            const double height = corner.y / corner.w + origin.y;
            heights = {std::min(heights.x, height), std::max(heights.y, height)};
        }
    return heights;
}

}  // namespace

Sides sides_reached(const ocean::Camera& camera, float aspect, const glm::dvec3& origin, double reach) {
    const glm::dvec2 lens = lens_heights(camera, aspect, origin);
    if (lens.x > reach) return Sides::above;
    if (lens.y < -reach) return Sides::below;
    return Sides::both;
}

double water_reach(const step06::Sea& sea) { return 5 * std::sqrt(sea.height_variance()); }

void Waterline::declare(ocean::ParamRegistry& p) {
    const auto group = p.group("underwater");
    p.add_choice("waterline_view", &view_, {"picture", "sides"},
                 "sides: each pixel red where the lens is above the water, blue below (green: neither)");
}

void Waterline::bind_below_target(glm::ivec2 size) {
    if (size != below_size_) {
        below_picture_ = ocean::make_colour_texture_2d(size.x, size.y, nullptr);
        below_target_ = ocean::make_framebuffer();
        ocean::attach_texture_2d(below_target_, GL_COLOR_ATTACHMENT0, below_picture_);
        below_size_ = size;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, below_target_.id());
    glViewport(0, 0, size.x, size.y);
}

void Waterline::draw_side(const step06::Sea& sea, const glm::mat4& view_projection, Sides side, bool paint,
                          GLuint fullscreen_vao) {
    ocean::ShaderProgram* p =
        programs_("waterline", {"fullscreen.vert", "step10_underwater/shaders/waterline.frag"}, sea.shader_defines());
    if (p == nullptr) return;
    sea.bind_maps(*p);
    p->set("u_inverse_view_projection", glm::inverse(view_projection));
    p->set("u_keep_below", int(side == Sides::below));
    p->set("u_paint", int(paint));
    if (!paint) ocean::bind_texture(UNIT_BELOW_PICTURE, GL_TEXTURE_2D, below_picture_.id());
    glUseProgram(p->id());
    glBindVertexArray(fullscreen_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Waterline::compose(const step06::Sea& sea, const glm::mat4& view_projection, GLuint fullscreen_vao) {
    draw_side(sea, view_projection, Sides::below, false, fullscreen_vao);
}

void Waterline::paint_sides(const step06::Sea& sea, const glm::mat4& view_projection, Sides drawn, GLuint fullscreen_vao) {
    glClearColor(0, 1, 0, 1);  // green: a pixel neither side's picture covers
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (drawn != Sides::below) draw_side(sea, view_projection, Sides::above, true, fullscreen_vao);
    if (drawn != Sides::above) draw_side(sea, view_projection, Sides::below, true, fullscreen_vao);
}

}  // namespace step10
