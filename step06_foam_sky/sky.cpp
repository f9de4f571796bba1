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
#include <iostream>
#include <sys/stat.h>

namespace step06 {

namespace {
constexpr const char* kShaders = "step06_foam_sky/shaders/";
}

Sky::Sky(ocean::ProgramFactory programs, int size) : programs_(std::move(programs)), size_(size) {
    cubemap_ = ocean::make_texture(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(cubemap_.id(), step05::mip_levels(size), GL_RGBA16F, size, size);
    glTextureParameteri(cubemap_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(cubemap_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    horizon_ = ocean::make_texture(GL_TEXTURE_1D);
    glTextureStorage1D(horizon_.id(), 1, GL_RGBA32F, kHorizonTexels);
    glTextureParameteri(horizon_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(horizon_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(horizon_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);  // the horizon goes round
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
    struct stat info {};
    if (stat(path.c_str(), &info) != 0)
        return "sky_image '" + path + "': " + std::strerror(errno) + "; using the procedural sky";
    if (S_ISDIR(info.st_mode)) return "sky_image '" + path + "' is a directory; using the procedural sky";
    int w = 0, h = 0, channels = 0;
    // .hdr loads as linear radiance; an LDR image (PNG, JPEG) is sRGB, which stb turns into
    // linear floats with its gamma (2.2 by default).
    float* pixels = stbi_loadf(path.c_str(), &w, &h, &channels, 3);
    if (pixels == nullptr)
        return "sky_image '" + path + "' is not a readable image (" + stbi_failure_reason() +
               "); using the procedural sky";
    equirect_ = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(equirect_.id(), 1, GL_RGB32F, w, h);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(equirect_.id(), 0, 0, 0, w, h, GL_RGB, GL_FLOAT, pixels);
    glTextureParameteri(equirect_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(equirect_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(equirect_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    stbi_image_free(pixels);
    return std::nullopt;
}

void Sky::render(const SkySettings& s) {
    if (equirect_ && image_rendered_) return;
    ocean::ShaderProgram* p = programs_(equirect_ ? "sky_equirect.comp" : "sky_cube.comp",
                                        {std::string(kShaders) + (equirect_ ? "sky_equirect.comp" : "sky_cube.comp")}, {});
    if (p == nullptr) throw ocean::Error("the sky shader does not build");
    p->set("u_size", size_);
    if (equirect_) {
        p->set("u_equirect", 0);
        glBindTextureUnit(0, equirect_.id());
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
    glBindImageTexture(0, cubemap_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glUseProgram(p->id());
    glDispatchCompute(GLuint((size_ + 7) / 8), GLuint((size_ + 7) / 8), 6);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // Rough reflections read the blurrier levels.
    step05::make_box_mipmaps(programs_, cubemap_.id());
    tabulate_horizon();
    image_rendered_ = bool(equirect_);
}

void Sky::bind() const {
    glBindTextureUnit(UNIT_SKY, cubemap_.id());
    glBindTextureUnit(UNIT_SKY_HORIZON, horizon_.id());
}

void Sky::tabulate_horizon() {
    ocean::ShaderProgram* p = programs_("sky_horizon.comp", {std::string(kShaders) + "sky_horizon.comp"}, {});
    if (p == nullptr) throw ocean::Error("sky_horizon.comp does not build");
    p->set("u_lod", horizon_lod());
    glBindTextureUnit(UNIT_SKY, cubemap_.id());
    glBindImageTexture(0, horizon_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(p->id());
    glDispatchCompute(GLuint((kHorizonTexels + 63) / 64), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
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
