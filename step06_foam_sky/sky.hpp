// Chapter 5.5's sky as a cubemap: rendered procedurally each frame (gradient, sun, drifting
// clouds: sky.glsl), or filled once from an equirectangular image (--set sky_image=FILE, HDR or
// LDR through stb_image). The sea reflects it and the background shows it. Each face is drawn as
// a full-screen pass into that face (sky_cube.frag), so the sky needs no compute shader and is the
// same code in every GL profile.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace step06 {

struct SkySettings {
    glm::vec3 to_sun{0, 1, 0};
    glm::vec3 sun_radiance{20.0f};  // linear
    glm::vec3 zenith{0.1f, 0.25f, 0.6f}, horizon{0.6f, 0.7f, 0.85f};  // linear
    float cloud_cover = 0.4f;
    glm::vec2 cloud_offset{0.0f};
    float sun_size = 0.02f;  // angular radius, radians
    float sun_disc_gain = 40;  // how much brighter the disc is than the light it casts
};

class Sky {
public:
    Sky(ocean::ProgramFactory programs, int size);
    // Loads an equirectangular image for the sky. On failure returns the warning to show and
    // keeps (or goes back to) the procedural sky. An empty path means the procedural sky.
    std::optional<std::string> use_image(const std::string& path);
    void render(const SkySettings& settings);  // procedural: every call; image: once
    // Once a frame: use_image(image) when `image_version` (the sky_image parameter's Generation)
    // moved since the last call (a file that cannot be read is a warning on stderr, and the
    // procedural sky), then render(settings); draw_background uses the same settings.
    void update(const SkySettings& settings, const std::string& image, unsigned image_version);
    // The sky behind the sea and the sun's disc, where the sea left the depth at the far plane
    // (sky.frag). The disc is drawn here, not kept in the cubemap: the water's specular term is
    // the sun's reflection, and a disc in the reflected sky would count it twice.
    void draw_background(const glm::mat4& view_projection, GLuint fullscreen_vao);

    GLuint cubemap() const { return cubemap_.id(); }
    // The fog's colour around the horizon (sky_horizon.glsl): kHorizonTexels of the cube at
    // horizon_lod, made by every render.
    GLuint horizon() const { return horizon_.id(); }
    // Both, on their units (texture_units.h: UNIT_SKY, UNIT_SKY_HORIZON), for a pass that shades
    // with the sky: a shader reading one has the other at hand.
    void bind() const;
    int size() const { return size_; }
    float max_lod() const;
    // The cube's level the fog reads: halfway to the coarsest (a texel there spans 6 to 11
    // degrees), so that the fog takes the horizon's colour, not each cloud's.
    float horizon_lod() const { return 0.5f * max_lod(); }
    bool uses_image() const { return bool(equirect_); }

private:
    void draw_faces(const ocean::ShaderProgram& program);  // program drawn into each face, level 0
    void tabulate_horizon();  // sky_horizon.frag, from the cube just made

    ocean::ProgramFactory programs_;
    int size_;
    ocean::Texture cubemap_, equirect_, horizon_;
    ocean::Framebuffer face_targets_[6], horizon_target_;  // level 0 of each face; the horizon's row
    ocean::VertexArray no_vertices_;  // the full-screen triangle's corners come from gl_VertexID
    bool image_rendered_ = false;
    unsigned image_version_ = 0;  // update()'s last image_version
    SkySettings settings_;        // update()'s
};

// sky.glsl's clouds, the CPU reference: lattice_hash(x, y) in [0, 1) from integers alone (PCG),
// value_noise smooth between the lattice points, clouds five octaves of it (0 to 31/32).
std::uint32_t pcg_hash(std::uint32_t v);
double lattice_hash(int x, int y);
double value_noise(glm::dvec2 p);
double clouds(glm::dvec2 p);

// sky_horizon.glsl's table of the fog's colour, the CPU reference: the coordinate of horizontal
// direction (x, z) (the "diamond angle" over 4: 0 at +x, 1/4 at +z, growing with the azimuth;
// negative towards -z, where the table repeats), and the direction (on |x| + |z| = 1) at u in [0, 1).
constexpr int kHorizonTexels = 256;  // HORIZON_TEXELS
double horizon_coordinate(glm::dvec2 d);
glm::dvec2 horizon_direction(double u);

// The direction through the centre of texel (x, y) of cubemap face `face` (the GL layout,
// as cube_faces.glsl): the tests find the sun's texel with it.
glm::vec3 cube_texel_direction(int face, int x, int y, int size);

}  // namespace step06
