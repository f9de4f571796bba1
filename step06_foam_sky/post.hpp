// Chapter 5.5's image passes: the scene is lit in linear HDR (an RGBA16F target), then bloom (a
// quarter-size level, a chain of half-size levels below it, a tent filter back up) and a filmic tonemapper bring it to the
// screen in sRGB.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step06 {

constexpr int kBloomLevels = 5;  // 1/4 of the screen down to 1/64: the same widest glow as before

// What the image passes do this frame (LookParams::post): a debug view is shown as it is, with no
// bloom, no filmic curve and no dither.
struct PostSettings {
    bool bloom = true;
    float bloom_threshold = 2.5f, bloom_strength = 0.06f;  // linear brightness; fraction of the glow added
    float exposure = 1;
    int tonemapper = 0;  // tonemap.frag's TONEMAPPER: 0 ACES, 1 AgX, 2 a clamp
    bool dither = true;
};

class PostProcess {
public:
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // The frame's HDR scene, (re)made for `size`, bound and cleared (black, depth at the far plane).
    void begin(glm::ivec2 size);
    // Bloom from the scene (when settings.bloom), then the scene and its glow through the exposure,
    // the tonemapper and sRGB into the framebuffer bound on entry (the window's).
    void bloom(const PostSettings& settings, GLuint fullscreen_vao) const;
    void tonemap(const PostSettings& settings, GLuint fullscreen_vao) const;

    void resize(glm::ivec2 size);  // (re)makes the targets when the window size changes
    void bind_scene() const;       // the HDR target, with its depth buffer
    GLuint scene_framebuffer() const { return scene_target_.id(); }
    GLuint scene_texture() const { return scene_.id(); }
    GLuint depth_texture() const { return depth_.id(); }
    GLuint bloom_texture() const { return bloom_views_.empty() ? 0 : bloom_views_[0].id(); }

    // Fills the bloom chain from the scene. `first` and `down`: bloom_down.frag with FIRST_LEVEL 1
    // and 0; `up`: bloom_up.frag.
    void bloom(const ocean::ShaderProgram& first, const ocean::ShaderProgram& down, const ocean::ShaderProgram& up,
               float threshold, GLuint fullscreen_vao) const;

private:
    ocean::ProgramFactory programs_;
    glm::ivec2 size_{0};
    ocean::Texture scene_, depth_, bloom_;
    std::vector<ocean::Texture> bloom_views_;  // one view per level: no sampling of the level being drawn
    ocean::Framebuffer scene_target_;
    std::vector<ocean::Framebuffer> bloom_targets_;
    std::vector<glm::ivec2> bloom_sizes_;
};

}  // namespace step06
