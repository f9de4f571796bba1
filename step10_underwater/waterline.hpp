// The waterline: where the camera goes through the surface. A camera's picture starts on its
// lens, the rectangle of the near plane in front of the eye; a wave passing the lens covers part
// of it, and that part of the picture is seen from the water while the rest is seen from the air.
// So each pixel is drawn from the side of the surface its point on the lens is on: the frame draws
// step06's sea from above, this chapter's from below, or both, put together along the line where
// the wave's surface crosses the lens (waterline.frag).
#pragma once

#include "common/camera.hpp"
#include "common/gl.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/sea.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <string>

namespace step10 {

enum class Sides { above, below, both };

// Which sides of the surface the camera's lens can be on, the waves lifting or lowering the water
// by at most `reach` metres: `origin` is the sea's world origin.
Sides sides_reached(const ocean::Camera& camera, float aspect, const glm::dvec3& origin, double reach);
// How far the water at a point can rise or fall: the height there is the sum of many waves, a
// Gaussian of the sea's variance, and five standard deviations are passed about once in three
// million looks (whatever sideways displacement does, it moves heights the field already has).
double water_reach(const step06::Sea& sea);

class Waterline {
public:
    void declare(ocean::ParamRegistry& p);
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // The sides view: each pixel painted by the side its lens point is on (red above, blue below),
    // among the sides the frame draws; a pixel the frame would leave to neither stays green.
    bool shows_sides() const { return view_ == kSidesView; }

    // Binds the framebuffer the picture below the surface is drawn into when both are drawn,
    // (re)made at `size`.
    void bind_below_target(glm::ivec2 size);
    // Puts that picture over the bound one (from above) where the lens is under the water.
    void compose(const step06::Sea& sea, const glm::mat4& view_projection, GLuint fullscreen_vao);
    // The sides view of a frame that draws `drawn`, into the bound framebuffer.
    void paint_sides(const step06::Sea& sea, const glm::mat4& view_projection, Sides drawn, GLuint fullscreen_vao);

private:
    static constexpr int kSidesView = 1;
    // Draws the pixels whose lens point is on `side` (above or below): the below picture, or in
    // the sides view the side's colour.
    void draw_side(const step06::Sea& sea, const glm::mat4& view_projection, Sides side, bool paint,
                   GLuint fullscreen_vao);

    ocean::ProgramFactory programs_;
    int view_ = 0;  // 0: the picture, 1: the sides
    ocean::Texture below_picture_;
    ocean::Framebuffer below_target_;
    glm::ivec2 below_size_{0};
};

}  // namespace step10
