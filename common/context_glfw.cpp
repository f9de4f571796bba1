// Windowed GL through GLFW: a debug context of the build's profile (GL 4.5 or 4.1 core, ES 3.0),
// vsync on. And, where the build has no EGL (macOS, Windows, or OCEAN_EGL off), the headless
// context too: a hidden GLFW window whose context draws into an offscreen framebuffer of the
// requested size, as EGL's does, so screenshots and goldens are the same.
#include "common/context.hpp"
#include "common/error.hpp"
#include "common/gl_profile.hpp"
#include "common/headless_context.hpp"

#include <GLFW/glfw3.h>

#include <cstdlib>

namespace ocean {

#if defined(OCEAN_EGL)
std::unique_ptr<Context> make_egl_context(const ContextOptions& options);
#endif

namespace {

// A GLFW window with a current context of the build's profile and the GL functions loaded; shown
// or hidden. Throws ocean::Error with one line.
GLFWwindow* open_window(const ContextOptions& options, bool visible) {
    glfwSetErrorCallback(nullptr);  // failures are reported below, in one line
    if (glfwInit() != GLFW_TRUE) throw Error("GLFW cannot start (is DISPLAY set to a running X server?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kBuildGlMajor);  // the build's profile (gl_profile.hpp)
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kBuildGlMinor);
    if (kBuildIsEs) {
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    } else {
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS gives 4.1 core only so
    }
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, visible ? options.samples : 0);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    // Hidden, the window is only the context's home: the pixels go to an offscreen framebuffer.
    GLFWwindow* window = visible ? glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr)
                                 : glfwCreateWindow(64, 64, options.title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        const char* reason = nullptr;
#if !defined(__EMSCRIPTEN__)  // emscripten's GLFW has no glfwGetError
        glfwGetError(&reason);
#endif
        glfwTerminate();
        throw Error(std::string("cannot open a ") + (visible ? "" : "hidden ") + "window with OpenGL " +
                    profile_name(kBuildProfile) + (reason ? std::string(": ") + reason : std::string()));
    }
    glfwMakeContextCurrent(window);
    if (load_gl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
        glfwDestroyWindow(window);
        glfwTerminate();
        throw Error(std::string("cannot load the OpenGL ") + profile_name(kBuildProfile) + " functions through GLFW");
    }
    return window;
}

class GlfwContext final : public Context {
public:
    explicit GlfwContext(const ContextOptions& options) : window_(open_window(options, true)) {
        glfwSwapInterval(1);
        description_ = describe_current_gl("GLFW window");
    }

    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    bool headless() const override { return false; }
    bool should_close() const override { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
    void request_close() override { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
    void poll_events() override { glfwPollEvents(); }
    // In a page the browser shows the frame when the frame's callback returns (App::browser_frame).
    void swap_buffers() override { glfwSwapBuffers(window_); }
    glm::ivec2 framebuffer_size() const override {
        glm::ivec2 size;
        glfwGetFramebufferSize(window_, &size.x, &size.y);
        return size;
    }
    GLuint target_framebuffer() const override { return 0; }
    GLFWwindow* window() const override { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

#if !defined(OCEAN_EGL) && !defined(__EMSCRIPTEN__)
// Headless without EGL: a hidden window's context, drawing into an offscreen framebuffer of the
// requested size. It needs a window system (on Linux a display: Xvfb where there is none).
class HiddenWindowContext final : public HeadlessContext {
public:
    explicit HiddenWindowContext(const ContextOptions& options)
        : HeadlessContext({options.width, options.height}), window_(open_window(options, false)) {
        description_ = describe_current_gl("hidden GLFW window");
        make_target();
    }

    ~HiddenWindowContext() override {
        release_target();
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

private:
    GLFWwindow* window_;
};
#endif

}  // namespace

bool display_available() {
#if defined(__EMSCRIPTEN__) || defined(__APPLE__) || defined(_WIN32)
    return true;  // the page's canvas; the desktop of macOS and of Windows
#endif
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

std::string describe_current_gl(const std::string& platform) {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < kBuildGlMajor || (major == kBuildGlMajor && minor < kBuildGlMinor))
        throw Error(std::string("OpenGL ") + profile_name(kBuildProfile) + " is required, this context offers " +
                    std::to_string(major) + "." + std::to_string(minor));
    const auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    // A driver may give a later version than the build asks for; the portable build still calls
    // only GL 4.1 (the ES build ES 3.0) and compiles its shaders for it: say so.
    const std::string profile = kBuildProfile == GlProfile::Core45 ? "" : std::string("; used as ") + profile_name(kBuildProfile);
    return text(GL_RENDERER) + " / OpenGL " + text(GL_VERSION) + " (" + platform + profile + ")";
}

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
#if defined(__EMSCRIPTEN__)
    if (options.headless) throw Error("a page has no headless mode: it draws into its canvas");
#elif defined(OCEAN_EGL)
    if (options.headless) return make_egl_context(options);
#else
    if (options.headless) {
        if (!display_available())
            throw Error("this build has no EGL: its headless runs need a display (on Linux: xvfb-run -a COMMAND)");
        return std::make_unique<HiddenWindowContext>(options);
    }
#endif
    return std::make_unique<GlfwContext>(options);
}

}  // namespace ocean
