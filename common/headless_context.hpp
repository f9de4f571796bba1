// What the two headless contexts share (EGL's, context_egl.cpp; a hidden GLFW window's,
// context_glfw.cpp): where they draw, a framebuffer of the requested size with an 8-bit colour and
// a depth-stencil renderbuffer, whatever the platform (EGL has no window; a hidden window may be
// any size, and on a Retina display counts points, not pixels); no events, nothing to swap, and a
// close that is only asked for.
#pragma once

#include "common/context.hpp"
#include "common/gl.hpp"

#include <glm/vec2.hpp>

namespace ocean {

class HeadlessContext : public Context {
public:
    bool headless() const override { return true; }
    bool should_close() const override { return close_requested_; }
    void request_close() override { close_requested_ = true; }
    void poll_events() override {}
    void swap_buffers() override {}
    glm::ivec2 framebuffer_size() const override { return size_; }
    GLuint target_framebuffer() const override { return framebuffer_.id(); }
    GLFWwindow* window() const override { return nullptr; }

protected:
    explicit HeadlessContext(glm::ivec2 size) : size_(size) {}
    // Once the subclass's context is current (throws ocean::Error with one line when the GPU
    // cannot make the framebuffer); and, in its destructor, before the context goes.
    void make_target();
    void release_target();

private:
    glm::ivec2 size_;
    Renderbuffer color_, depth_;
    Framebuffer framebuffer_;
    bool close_requested_ = false;
};

}  // namespace ocean
