// The sunlight the waves focus on the seabed, computed as a lens makes it: a grid of the sun's
// rays, each refracted where it meets the moving surface and carried down to the seabed
// (caustic_rays.frag), where the light between neighbouring rays is drawn into a texture of the
// seabed around the camera, as triangles or, where they land smaller than a texel, as points
// (caustic_cells.glsl). A texel holds the irradiance there over a flat sea's: 1 where the surface
// is level, more where the crests gather light, less under the troughs that spread it.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <string>
#include <vector>

namespace step10 {

// The patch of seabed the caustics are computed over, and how finely.
struct CausticWindow {
    float size = 32;       // metres a side
    int resolution = 200;  // texels a side: 16 cm at 32 m
    int rays = 256;        // rays a side, over the window and a margin of a quarter of it
};

// What one frame's caustics are computed for.
struct CausticLight {
    glm::vec3 to_sun{0, 1, 0};  // unit, towards the sun (above the horizon)
    float seabed_depth = 12;    // metres below the mean level
    glm::vec2 around{0.0f};     // metres (x z) from the sea's world origin: the window's centre
};

class Caustics {
public:
    // Gives a program the surface it refracts the rays through: cascades.glsl's maps and uniforms
    // (step06::Sea::bind_maps, or a test's own sea).
    using BindSea = std::function<void(const ocean::ShaderProgram&)>;

    // Draws the pattern for `light` over `window`; `defines` are those cascades.glsl is compiled
    // with (step06::Sea::shader_defines). False when there is none: the GL cannot draw into the
    // texture (a warning said so, once) or the shader did not build; the seabed is then lit evenly.
    bool update(const ocean::ProgramFactory& programs, const std::vector<std::string>& defines, const BindSea& bind_sea,
                const CausticWindow& window, const CausticLight& light);

    GLuint texture() const { return texture_.id(); }  // RGBA16F, r: irradiance over a flat sea's
    glm::vec2 centre() const { return centre_; }      // metres (x z): the window's centre,
    float size() const { return size_; }              // and its side, when last drawn
    bool failed() const { return failed_; }

private:
    bool make_texture(int resolution);
    bool make_grid(int rays);
    bool cannot_draw();

    ocean::Texture texture_;
    ocean::Framebuffer target_;
    int texture_resolution_ = 0;
    bool failed_ = false;
    ocean::Texture rays_, transmitted_;  // a texel a ray (caustic_rays.frag)
    ocean::Framebuffer rays_target_;
    ocean::Buffer grid_indices_;
    ocean::VertexArray grid_vao_;
    int grid_rays_ = 0;
    GLsizei grid_index_count_ = 0;
    glm::vec2 centre_{0.0f};
    float size_ = 0;
};

}  // namespace step10
