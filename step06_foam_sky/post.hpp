// Chapter 5.5's image passes: the scene is lit in linear HDR (an RGBA16F target), then bloom (a
// quarter-size level, a chain of half-size levels below it, a tent filter back up) and a filmic tonemapper bring it to the
// screen in sRGB.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step06 {

constexpr int kTonemapNone = 2;  // the tonemapper parameter's third choice, tonemap.frag's TONEMAPPER 2
constexpr int kBloomLevels = 5;  // 1/4 of the screen down to 1/64: the same widest glow as before

// What the image passes do this frame (LookParams::post): a debug view is shown as it is, with no
// bloom and no filmic curve.
struct PostSettings {
    bool bloom;
    float bloom_threshold, bloom_strength;  // linear brightness; fraction of the glow added
    float exposure;
    int tonemapper;  // tonemap.frag's TONEMAPPER: 0 ACES, 1 AgX, 2 none (the values clamped, to measure)
};

class PostProcess {
public:
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // The frame's HDR scene, (re)made for `size`, bound and cleared (black, depth at the far plane).
    void begin(glm::ivec2 size);
    // Bloom from the scene (when settings.bloom), then the scene and its glow through the exposure,
    // the tonemapper and sRGB into the framebuffer bound on entry (the window's). A filmic curve
    // is dithered (one 8-bit step of triangular noise against banding); none is not.
    void bloom(const PostSettings& settings, GLuint fullscreen_vao) const;
    void tonemap(const PostSettings& settings, GLuint fullscreen_vao) const;

    void resize(glm::ivec2 size);  // (re)makes the targets when the window size changes
    void bind_scene() const;       // the HDR target, with its depth buffer
    GLuint scene_framebuffer() const { return scene_target_.id(); }
    GLuint scene_texture() const { return scene_.id(); }
    GLuint depth_texture() const { return depth_.id(); }
    GLuint bloom_texture() const { return bloom_levels_.empty() ? 0 : bloom_levels_[0].id(); }

    // Fills the bloom chain from the scene. `first` and `down`: bloom_down.frag with FIRST_LEVEL 1
    // and 0; `up`: bloom_up.frag.
    void bloom(const ocean::ShaderProgram& first, const ocean::ShaderProgram& down, const ocean::ShaderProgram& up,
               float threshold, GLuint fullscreen_vao) const;

private:
    ocean::ProgramFactory programs_;
    glm::ivec2 size_{0};
    ocean::Texture scene_, depth_;
    std::vector<ocean::Texture> bloom_levels_;  // a quarter of the screen, then halves
    ocean::Framebuffer scene_target_;
    std::vector<ocean::Framebuffer> bloom_targets_;
    std::vector<glm::ivec2> bloom_sizes_;
};

}  // namespace step06
