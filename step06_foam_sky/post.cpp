#include "step06_foam_sky/post.hpp"

#include "step06_foam_sky/bloom.hpp"

#include "common/gl_texture.hpp"

#include <string>
#include <utility>

namespace step06 {

void PostProcess::resize(glm::ivec2 size) {
    if (size == size_ || size.x <= 0 || size.y <= 0) return;
    size_ = size;
    scene_ = ocean::make_linear_float_texture_2d(GL_RGBA16F, size.x, size.y, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
    depth_ = ocean::make_float_texture_2d(GL_DEPTH_COMPONENT32F, size.x, size.y);
    scene_target_ = ocean::make_framebuffer();
    ocean::attach_texture_2d(scene_target_, GL_COLOR_ATTACHMENT0, scene_);
    ocean::attach_texture_2d(scene_target_, GL_DEPTH_ATTACHMENT, depth_);

    // Bloom level 0 is a quarter of the screen each way; each next level half the previous (at
    // least 1 pixel). A glow is blurry by nature: a half-size first level cost 16 ms of llvmpipe's
    // frame (its 13 taps read the whole screen) and added only the tightest 2-pixel halo, which
    // the scene itself already shows. A tiny window has fewer levels: a texture cannot have more
    // than log2(side) + 1. Each level is a texture of its own, read with linear filtering: a pass
    // samples the level above while it draws into the next, never the level it draws into.
    bloom_sizes_ = bloom_level_sizes(size, kBloomLevels);  // bloom.hpp
    bloom_levels_.clear();
    bloom_targets_.clear();
    for (glm::ivec2 level_size : bloom_sizes_) {
        bloom_levels_.push_back(ocean::make_linear_float_texture_2d(GL_RGBA16F, level_size.x, level_size.y,
                                                                    GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE));
        ocean::Framebuffer target = ocean::make_framebuffer();
        ocean::attach_texture_2d(target, GL_COLOR_ATTACHMENT0, bloom_levels_.back());
        bloom_targets_.push_back(std::move(target));
    }
}

void PostProcess::begin(glm::ivec2 size) {
    resize(size);
    bind_scene();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void PostProcess::bloom(const PostSettings& settings, GLuint fullscreen_vao) const {
    if (!settings.bloom) return;
    const std::string frag = "step06_foam_sky/shaders/bloom_down.frag";
    ocean::ShaderProgram* first = programs_("bloom_first", {"fullscreen.vert", frag}, {"FIRST_LEVEL 1"});
    ocean::ShaderProgram* down = programs_("bloom_down", {"fullscreen.vert", frag}, {});
    ocean::ShaderProgram* up = programs_("bloom_up", {"fullscreen.vert", "step06_foam_sky/shaders/bloom_up.frag"}, {});
    if (first != nullptr && down != nullptr && up != nullptr)
        bloom(*first, *down, *up, settings.bloom_threshold, fullscreen_vao);
}

void PostProcess::tonemap(const PostSettings& settings, GLuint fullscreen_vao) const {
    ocean::ShaderProgram* tonemap =
        programs_("tonemap", {"fullscreen.vert", "step06_foam_sky/shaders/tonemap.frag"},
                  {"TONEMAPPER " + std::to_string(settings.tonemapper),
                   std::string("DITHER ") + (settings.tonemapper != kTonemapNone ? "1" : "0")});
    if (tonemap == nullptr) return;
    tonemap->set("u_scene", 0);
    tonemap->set("u_bloom", 1);
    tonemap->set("u_exposure", settings.exposure);
    tonemap->set("u_bloom_strength", settings.bloom ? settings.bloom_strength : 0.0f);
    ocean::bind_texture(0, GL_TEXTURE_2D, scene_texture());
    ocean::bind_texture(1, GL_TEXTURE_2D, bloom_texture());
    glUseProgram(tonemap->id());
    glBindVertexArray(fullscreen_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void PostProcess::bind_scene() const {
    glBindFramebuffer(GL_FRAMEBUFFER, scene_target_.id());
    glViewport(0, 0, size_.x, size_.y);
}

void PostProcess::bloom(const ocean::ShaderProgram& first, const ocean::ShaderProgram& down,
                        const ocean::ShaderProgram& up, float threshold, GLuint fullscreen_vao) const {
    glBindVertexArray(fullscreen_vao);
    for (std::size_t level = 0; level < bloom_targets_.size(); ++level) {
        const bool from_scene = level == 0;
        const ocean::ShaderProgram& p = from_scene ? first : down;
        glUseProgram(p.id());
        p.set("u_source", 0);
        if (from_scene) p.set("u_threshold", threshold);
        p.set("u_source_texel", 1.0f / glm::vec2(from_scene ? size_ : bloom_sizes_[level - 1]));
        ocean::bind_texture(0, GL_TEXTURE_2D, from_scene ? scene_.id() : bloom_levels_[level - 1].id());
        glBindFramebuffer(GL_FRAMEBUFFER, bloom_targets_[level].id());
        glViewport(0, 0, bloom_sizes_[level].x, bloom_sizes_[level].y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glUseProgram(up.id());
    up.set("u_source", 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (std::size_t level = bloom_targets_.size() - 1; level > 0; --level) {
        up.set("u_source_texel", 1.0f / glm::vec2(bloom_sizes_[level]));
        ocean::bind_texture(0, GL_TEXTURE_2D, bloom_levels_[level].id());
        glBindFramebuffer(GL_FRAMEBUFFER, bloom_targets_[level - 1].id());
        glViewport(0, 0, bloom_sizes_[level - 1].x, bloom_sizes_[level - 1].y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_BLEND);
}

}  // namespace step06
