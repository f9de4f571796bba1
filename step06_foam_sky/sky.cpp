#include "step06_foam_sky/sky.hpp"

#include "common/error.hpp"
#include "step05_fft/box_mipmaps.hpp"
#include "step06_foam_sky/far_plane.hpp"
#include "step06_foam_sky/texture_units.h"

#include <stb_image.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace step06 {

namespace {
constexpr const char* kShaders = "step06_foam_sky/shaders/";
}

Sky::Sky(ocean::ProgramFactory programs, int size) : programs_(std::move(programs)), size_(size) {
    cubemap_ = ocean::make_cube_texture(GL_RGBA16F, size, step05::mip_levels(size));
    for (int face = 0; face < 6; ++face) {
        face_targets_[face] = ocean::make_framebuffer();
        if (!ocean::attach_cube_face(face_targets_[face], GL_COLOR_ATTACHMENT0, cubemap_, face))
            throw ocean::Error("this GL cannot render into a half-float cubemap (the sky's)");
    }
    // One row that goes round the horizon: repeating along it.
    horizon_ = ocean::make_linear_float_texture_2d(GL_RGBA32F, kHorizonTexels, 1, GL_REPEAT, GL_CLAMP_TO_EDGE);
    horizon_target_ = ocean::make_framebuffer();
    if (!ocean::attach_texture_2d(horizon_target_, GL_COLOR_ATTACHMENT0, horizon_))
        throw ocean::Error("this GL cannot render into 32-bit float textures (the fog's horizon table)");
    no_vertices_ = ocean::make_vertex_array();
}

void Sky::update(const SkySettings& settings, const std::string& image, unsigned image_version) {
    if (image_version != image_version_) {
        image_version_ = image_version;
        if (auto warning = use_image(image)) std::cerr << "warning: " << *warning << "\n";
    }
    settings_ = settings;
    render(settings_);
}

// Drawn last, and only where the sea left the depth at the far plane: drawn first, under
// everything, most of its pixels would be drawn again by the sea.
void Sky::draw_background(const glm::mat4& view_projection, GLuint fullscreen_vao) {
    ocean::ShaderProgram* sky = programs_("sky", {"fullscreen.vert", std::string(kShaders) + "sky.frag"}, {});
    if (sky == nullptr) return;
    sky->set("u_to_sun", settings_.to_sun);
    sky->set("u_sun_radiance", settings_.sun_radiance);
    sky->set("u_sun_size", settings_.sun_size);
    sky->set("u_draw_sun_disc", int(!uses_image()));
    sky->set("u_inverse_view_projection", glm::inverse(view_projection));
    bind();
    glUseProgram(sky->id());
    draw_at_far_plane(GL_LEQUAL, fullscreen_vao);
}

float Sky::max_lod() const { return float(step05::mip_levels(size_) - 1); }  // the 1 x 1 level

std::optional<std::string> Sky::use_image(const std::string& path) {
    equirect_.reset();
    image_rendered_ = false;
    if (path.empty()) return std::nullopt;
    std::error_code missing;
    const auto status = std::filesystem::status(path, missing);
    if (missing) return "sky_image '" + path + "': " + missing.message() + "; using the procedural sky";
    if (std::filesystem::is_directory(status)) return "sky_image '" + path + "' is a directory; using the procedural sky";
    int w = 0, h = 0, channels = 0;
    // .hdr loads as linear radiance; an LDR image (PNG, JPEG) is sRGB, which stb turns into
    // linear floats with its gamma (2.2 by default). Four channels: ES cannot filter RGB32F.
    float* pixels = stbi_loadf(path.c_str(), &w, &h, &channels, 4);
    if (pixels == nullptr)
        return "sky_image '" + path + "' is not a readable image (" + stbi_failure_reason() +
               "); using the procedural sky";
    // Longitude repeats round the sky; latitude stops at the poles.
    equirect_ = ocean::make_linear_float_texture_2d(GL_RGBA32F, w, h, GL_REPEAT, GL_CLAMP_TO_EDGE, pixels);
    stbi_image_free(pixels);
    return std::nullopt;
}

void Sky::render(const SkySettings& s) {
    if (equirect_ && image_rendered_) return;
    const std::string file = equirect_ ? "sky_equirect.frag" : "sky_cube.frag";
    ocean::ShaderProgram* p = programs_(file, {"common/shaders/fullscreen.vert", std::string(kShaders) + file}, {});
    if (p == nullptr) throw ocean::Error("the sky shader " + file + " does not build");
    const ocean::OffscreenPassState keep(no_vertices_.id());  // what was bound, put back at the end
    glUseProgram(p->id());
    p->set("u_size", size_);
    if (equirect_) {
        p->set("u_equirect", 0);
        ocean::bind_texture(0, GL_TEXTURE_2D, equirect_.id());
    } else {
        p->set("u_to_sun", s.to_sun);
        p->set("u_sun_radiance", s.sun_radiance);
        p->set("u_zenith_colour", s.zenith);
        p->set("u_horizon_colour", s.horizon);
        p->set("u_cloud_cover", s.cloud_cover);
        p->set("u_cloud_offset", s.cloud_offset);
        p->set("u_sun_size", s.sun_size);
        p->set("u_sun_disc_gain", s.sun_disc_gain);
    }
    draw_faces(*p);
    step05::make_mipmaps(programs_, cubemap_, GL_TEXTURE_CUBE_MAP);  // rough reflections read the blurrier levels
    tabulate_horizon();
    image_rendered_ = bool(equirect_);
}

// One full-screen triangle into each face: a fragment a texel, the face in u_face.
void Sky::draw_faces(const ocean::ShaderProgram& program) {
    glViewport(0, 0, size_, size_);
    for (int face = 0; face < 6; ++face) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, face_targets_[face].id());
        program.set("u_face", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

void Sky::bind() const {
    ocean::bind_texture(UNIT_SKY, GL_TEXTURE_CUBE_MAP, cubemap_.id());
    ocean::bind_texture(UNIT_SKY_HORIZON, GL_TEXTURE_2D, horizon_.id());
}

void Sky::tabulate_horizon() {
    ocean::ShaderProgram* p = programs_("sky_horizon.frag", {"common/shaders/fullscreen.vert", std::string(kShaders) + "sky_horizon.frag"}, {});
    if (p == nullptr) throw ocean::Error("the sky shader sky_horizon.frag does not build");
    const ocean::OffscreenPassState keep(no_vertices_.id());
    glUseProgram(p->id());
    p->set("u_lod", horizon_lod());
    ocean::bind_texture(UNIT_SKY, GL_TEXTURE_CUBE_MAP, cubemap_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, horizon_target_.id());
    glViewport(0, 0, kHorizonTexels, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

double horizon_coordinate(glm::dvec2 d) {
    const double s = d.y / std::max(std::abs(d.x) + std::abs(d.y), 1e-300);
    return 0.25 * (d.x >= 0 ? s : 2 - s);
}

glm::dvec2 horizon_direction(double u) {
    const double a = 4 * u;
    if (a < 1) return {1 - a, a};
    if (a < 2) return {1 - a, 2 - a};
    if (a < 3) return {a - 3, 2 - a};
    return {a - 3, a - 4};
}

std::uint32_t pcg_hash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

double lattice_hash(int x, int y) {
    return double(pcg_hash(std::uint32_t(x) + pcg_hash(std::uint32_t(y))) >> 8u) / 16777216.0;
}

double value_noise(glm::dvec2 p) {
    const double fx = std::floor(p.x), fy = std::floor(p.y);
    const int x = int(fx), y = int(fy);
    const double ax = p.x - fx, ay = p.y - fy;
    const double ux = ax * ax * (3 - 2 * ax), uy = ay * ay * (3 - 2 * ay);
    const auto mix = [](double a, double b, double t) { return a + (b - a) * t; };
    return mix(mix(lattice_hash(x, y), lattice_hash(x + 1, y), ux),
               mix(lattice_hash(x, y + 1), lattice_hash(x + 1, y + 1), ux), uy);
}

double clouds(glm::dvec2 p) {
    double sum = 0, amplitude = 0.5;
    for (int octave = 0; octave < 5; ++octave) {
        sum += amplitude * value_noise(p);
        p = p * 2.03 + glm::dvec2(17.0, 9.0);
        amplitude *= 0.5;
    }
    return sum;
}

glm::vec3 cube_texel_direction(int face, int x, int y, int size) {
    const float s = 2.0f * (float(x) + 0.5f) / float(size) - 1.0f, t = 2.0f * (float(y) + 0.5f) / float(size) - 1.0f;
    glm::vec3 d;
    switch (face) {
        case 0: d = {1, -t, -s}; break;
        case 1: d = {-1, -t, s}; break;
        case 2: d = {s, 1, t}; break;
        case 3: d = {s, -1, -t}; break;
        case 4: d = {s, -t, 1}; break;
        default: d = {-s, -t, -1}; break;
    }
    return glm::normalize(d);
}

}  // namespace step06
