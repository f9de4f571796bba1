// Where a headless context draws: a framebuffer of the requested size with an 8-bit colour and a
// depth-stencil renderbuffer. Its size is the --size asked for, whatever the platform (EGL has no
// window; a hidden GLFW window may be any size, and on a Retina display counts points, not pixels).
#pragma once

#include "common/gl.hpp"

#include <glm/vec2.hpp>

namespace ocean {

class OffscreenTarget {
public:
    // Needs a current context. Throws ocean::Error with one line when the GPU cannot make it.
    explicit OffscreenTarget(glm::ivec2 size);
    GLuint id() const { return framebuffer_.id(); }
    glm::ivec2 size() const { return size_; }

private:
    glm::ivec2 size_;
    Renderbuffer color_, depth_;
    Framebuffer framebuffer_;
};

}  // namespace ocean
