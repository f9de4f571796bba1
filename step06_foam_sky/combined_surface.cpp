#include "step06_foam_sky/combined_surface.hpp"

#include "common/error.hpp"
#include "step05_fft/box_mipmaps.hpp"
#include "step06_foam_sky/texture_units.h"

#include <string>

namespace step06 {

namespace {
ocean::Texture make_level_array(int n, int levels) {
    ocean::Texture texture = ocean::make_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(texture.id(), step05::mip_levels(n), GL_RGBA16F, n, n, levels);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // A point is read well inside its level (kLevelReach): the edge is never sampled across.
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}
}  // namespace

void CombinedSurface::resize(int n, int levels, double texel0) {
    if (n < 2 || (n & (n - 1)) != 0)
        throw ocean::Error("combined levels: " + std::to_string(n) + " texels is not a power of two");
    if (levels < 1 || levels > kMaxCombinedLevels)
        throw ocean::Error("combined levels: " + std::to_string(levels) + " levels (1 to " +
                           std::to_string(kMaxCombinedLevels) + ")");
    texel0_ = texel0;
    if (n == n_ && levels == levels_ && displacement_) return;
    n_ = n;
    levels_ = levels;
    displacement_ = make_level_array(n, levels);
    slopes_ = make_level_array(n, levels);
    windows_.assign(std::size_t(levels), TexelWindow{});
}

void CombinedSurface::update(const step05::OceanSimulation& ocean, const CascadeView& cascades,
                             glm::dvec2 eye_xz, int combined_cascades) {
    ocean::ShaderProgram* p = programs_("combine.comp", {"step06_foam_sky/shaders/combine.comp"}, {});
    if (p == nullptr) throw ocean::Error("combine.comp does not build");
    origin_ = cascades.origin;
    eye_xz_ = eye_xz;
    for (int level = 0; level < levels_; ++level) {
        const TexelWindow w = window_around(eye_xz, texel0_ * std::exp2(level), n_);
        windows_[std::size_t(level)] = w;
        const std::string index = "[" + std::to_string(level) + "]";
        p->set("u_origin" + index, w.origin - w.cell_of(origin_));  // cells from the world origin
        p->set("u_texel_size" + index, float(w.texel_size));
    }
    combined_cascades_ = combined_cascades;
    CascadeView in_levels = cascades;  // the cascades the levels hold
    for (int c = combined_cascades; c < kCascades; ++c) in_levels.enabled[std::size_t(c)] = false;
    in_levels.upload(*p);
    p->set("u_n", n_);
    p->set("u_levels", levels_);
    ocean.bind_maps(*p);
    glBindImageTexture(0, displacement_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(1, slopes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glUseProgram(p->id());
    const GLuint groups = GLuint((n_ + 7) / 8);
    glDispatchCompute(groups, groups, GLuint(levels_));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    step05::make_box_mipmaps(programs_, displacement_.id(), slopes_.id());
}

void CombinedSurface::bind(const ocean::ShaderProgram& program) const {
    std::vector<glm::vec2> corners;
    for (const TexelWindow& w : windows_) corners.emplace_back(glm::dvec2(w.origin) * w.texel_size - origin_);
    program.set("u_combined_levels", levels_);
    program.set("u_combined_cascades", combined_cascades_);
    program.set("u_combined_n", n_);
    program.set("u_combined_side0", float(texel0_ * n_));
    program.set("u_combined_centre", glm::vec2(eye_xz_ - origin_));
    program.set("u_combined_corner", corners);
    glBindTextureUnit(UNIT_COMBINED_DISPLACEMENT, displacement_.id());
    glBindTextureUnit(UNIT_COMBINED_SLOPES, slopes_.id());
}

std::vector<glm::vec4> CombinedSurface::read_level(int level, bool slopes) const {
    std::vector<glm::vec4> out(std::size_t(n_) * std::size_t(n_));
    glGetTextureSubImage((slopes ? slopes_ : displacement_).id(), 0, 0, 0, level, n_, n_, 1, GL_RGBA,
                         GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)), out.data());
    return out;
}

}  // namespace step06
