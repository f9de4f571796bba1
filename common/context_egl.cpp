// Headless GL through EGL: no window system at all. On GPU servers the EGL device platform
// reaches the real driver; on machines without a GPU, Mesa's surfaceless platform gives
// llvmpipe. Rendering goes into an offscreen framebuffer of the requested size.
#include "common/context.hpp"
#include "common/error.hpp"
#include "common/gl_profile.hpp"
#include "common/headless_context.hpp"

#include <glad/egl.h>

#include <cstring>
#include <vector>

namespace ocean {

namespace {

bool has_extension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglContext final : public HeadlessContext {
public:
    explicit EglContext(const ContextOptions& options) : HeadlessContext({options.width, options.height}) {
        // First load: only the client functions, enough to choose a platform.
        if (gladLoaderLoadEGL(EGL_NO_DISPLAY) == 0)
            throw Error("cannot load libEGL.so.1 (install libegl1 and libegl-mesa0)");
        const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        std::string platform;
        if (has_extension(client, "EGL_EXT_platform_device")) {
            display_ = open_gpu_device();
            if (display_ != EGL_NO_DISPLAY) platform = "EGL device";
        }
        if (display_ == EGL_NO_DISPLAY && has_extension(client, "EGL_MESA_platform_surfaceless")) {
            display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (display_ != EGL_NO_DISPLAY && eglInitialize(display_, nullptr, nullptr) != EGL_TRUE)
                display_ = EGL_NO_DISPLAY;
            if (display_ != EGL_NO_DISPLAY) platform = "EGL surfaceless";
        }
        if (display_ == EGL_NO_DISPLAY)
            throw Error("no headless EGL display: neither a GPU EGL device nor Mesa's surfaceless "
                        "platform is available");
        gladLoaderLoadEGL(display_);  // second load: the display's extensions too

        if (eglBindAPI(kBuildIsEs ? EGL_OPENGL_ES_API : EGL_OPENGL_API) != EGL_TRUE)
            throw Error(std::string("EGL cannot bind the OpenGL ") + (kBuildIsEs ? "ES " : "") + "API");
        const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, kBuildIsEs ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        eglChooseConfig(display_, config_attribs, &config, 1, &count);
        // ES has no profiles: the desktop builds ask for the core one.
        const EGLint profile = kBuildIsEs ? EGL_NONE : EGL_CONTEXT_OPENGL_PROFILE_MASK;
        const EGLint context_attribs[] = {
            EGL_CONTEXT_MAJOR_VERSION, kBuildGlMajor, EGL_CONTEXT_MINOR_VERSION, kBuildGlMinor,
            EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE,
            profile, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = eglCreateContext(display_, count > 0 ? config : EGL_NO_CONFIG_KHR,
                                    EGL_NO_CONTEXT, context_attribs);
        if (context_ == EGL_NO_CONTEXT)
            throw Error(std::string("EGL cannot create an OpenGL ") + profile_name(kBuildProfile) + " context (" + platform + ")");
        if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
            throw Error("EGL cannot make the context current without a surface (" + platform + ")");
        if (load_gl(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0)
            throw Error(std::string("cannot load the OpenGL ") + profile_name(kBuildProfile) + " functions through EGL");
        description_ = describe_current_gl(platform);
        make_target();
    }

    ~EglContext() override {
        release_target();
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
        gladLoaderUnloadEGL();
    }

private:
    // A device whose driver is not Mesa's software renderer, so a GPU server uses its GPU.
    EGLDisplay open_gpu_device() {
        EGLint count = 0;
        if (eglQueryDevicesEXT == nullptr || eglQueryDevicesEXT(0, nullptr, &count) != EGL_TRUE)
            return EGL_NO_DISPLAY;
        std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
        eglQueryDevicesEXT(count, devices.data(), &count);
        for (EGLDeviceEXT device : devices) {
            const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
            if (has_extension(extensions, "EGL_MESA_device_software")) continue;
            EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr) == EGL_TRUE)
                return display;
        }
        return EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> make_egl_context(const ContextOptions& options) {
    return std::make_unique<EglContext>(options);
}

}  // namespace ocean
