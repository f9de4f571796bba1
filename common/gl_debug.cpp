#include "common/gl_debug.hpp"

#include "common/gl.hpp"
#include "common/gl_profile.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(OCEAN_GL_ES) && !defined(__EMSCRIPTEN__)
// ES has KHR_debug as an extension only, whose names carry its suffix: the same values.
#define GL_DEBUG_OUTPUT GL_DEBUG_OUTPUT_KHR
#define GL_DEBUG_OUTPUT_SYNCHRONOUS GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR
#define GL_DEBUG_SOURCE_SHADER_COMPILER GL_DEBUG_SOURCE_SHADER_COMPILER_KHR
#define GL_DEBUG_SEVERITY_HIGH GL_DEBUG_SEVERITY_HIGH_KHR
#define GL_DEBUG_TYPE_ERROR GL_DEBUG_TYPE_ERROR_KHR
#define GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR_KHR
#define GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR_KHR
#define GL_DEBUG_TYPE_PORTABILITY GL_DEBUG_TYPE_PORTABILITY_KHR
#define GL_DEBUG_TYPE_PERFORMANCE GL_DEBUG_TYPE_PERFORMANCE_KHR
#define glDebugMessageCallback glDebugMessageCallbackKHR
#define glDebugMessageControl glDebugMessageControlKHR
#endif

namespace ocean {

namespace {

GlDebugStats g_stats;  // the GL callback has no user object we own; one context per process
bool g_verbose = false;

void record_error(const std::string& message) {
    if (g_stats.errors++ == 0) g_stats.first_error = message;
}

#if !defined(__EMSCRIPTEN__)  // WebGL has no debug output
const char* type_name(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR: return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
        case GL_DEBUG_TYPE_PORTABILITY: return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
        default: return "info";
    }
}

void GLAPIENTRY on_gl_message(GLenum source, GLenum type, GLuint /*id*/, GLenum severity,
                              GLsizei /*length*/, const GLchar* message, const void* /*user*/) {
    // A shader that fails to compile is not a GL error: the shader loader reports it in
    // file:line form (and keeps the last good program); the driver's copy would only repeat it.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) {
        if (g_verbose) std::fprintf(stderr, "GL shader compiler: %s\n", message);
        return;
    }
    const bool is_error = type == GL_DEBUG_TYPE_ERROR;
    const bool is_warning = type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
                            type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR ||
                            type == GL_DEBUG_TYPE_PORTABILITY || severity == GL_DEBUG_SEVERITY_HIGH;
    if (is_error) record_error(message);
    if (is_error || is_warning || g_verbose) std::fprintf(stderr, "GL %s: %s\n", type_name(type), message);
}
#endif

}  // namespace

void enable_gl_debug_output() {
    const char* env = std::getenv("OCEAN_GL_DEBUG");
    g_verbose = env != nullptr && std::strcmp(env, "verbose") == 0;
    g_stats = GlDebugStats();  // counts belong to this context
    // KHR_debug: core from GL 4.3, an extension before it and in ES (Mesa has it; macOS's 4.1 has
    // not, and there glGetError after each frame is what is left: check_gl_errors).
#if defined(__EMSCRIPTEN__)
    return;  // WebGL has no debug output: the browser's console shows its warnings
#else
    if (kBuildProfile != GlProfile::Core45 && !GLAD_GL_KHR_debug) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(on_gl_message, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
#endif
}

const GlDebugStats& gl_debug_stats() { return g_stats; }

void check_gl_errors(const char* where) {
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        char message[128];
        std::snprintf(message, sizeof message, "glGetError 0x%04x after %s", e, where);
        std::fprintf(stderr, "GL error: %s\n", message);
        record_error(message);
    }
}

}  // namespace ocean
