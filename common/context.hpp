// Where the pixels go: a GLFW window with a context of the build's profile, or a headless context
// rendering into an offscreen framebuffer: EGL's (the device platform when a GPU driver offers
// one, Mesa's surfaceless platform otherwise), or, in a build without EGL (macOS, Windows,
// OCEAN_EGL off), a hidden GLFW window's. The app draws into target_framebuffer() and never needs
// to know which; the first line a step prints says which (describe_current_gl's platform).
#pragma once

#include "common/gl.hpp"

#include <glm/vec2.hpp>

#include <memory>
#include <string>

struct GLFWwindow;

namespace ocean {

struct ContextOptions {
    bool headless = false;
    int width = 1280, height = 720;
    std::string title;
    int samples = 4;  // the window's multisampling (StepInfo::window_samples); headless: none
};

class Context {
public:
    // Throws ocean::Error with one line when no context can be made.
    static std::unique_ptr<Context> create(const ContextOptions& options);
    virtual ~Context() = default;

    virtual bool headless() const = 0;
    virtual bool should_close() const = 0;
    virtual void request_close() = 0;
    virtual void poll_events() = 0;
    virtual void swap_buffers() = 0;
    virtual glm::ivec2 framebuffer_size() const = 0;
    virtual GLuint target_framebuffer() const = 0;  // 0 for a window
    virtual GLFWwindow* window() const = 0;         // nullptr when headless
    // "NVIDIA GeForce ... / 4.5.0 NVIDIA ... (EGL device)" and the like.
    std::string description() const { return description_; }

protected:
    std::string description_;
};

// A display exists for GLFW to open a window on.
bool display_available();

// Fills `description` and checks the GL version once a context is current and glad is loaded.
std::string describe_current_gl(const std::string& platform);

}  // namespace ocean
