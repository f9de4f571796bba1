// The OpenGL profile a build targets, fixed when it is compiled:
//   Core45  GL 4.5 core, the default build: compute shaders, direct state access, tessellation.
//   Core41  GL 4.1 core, the `portable` build (OCEAN_GL_PORTABLE): what macOS offers. Its loader
//           (glad, gl:core=4.1) declares nothing newer, so a 4.5 call does not even compile.
//   Es30    OpenGL ES 3.0, what WebGL 2 offers: the `es` build (OCEAN_GL_ES, natively through
//           Mesa's ES driver, its loader glad's gles2=3.0) and the WebAssembly build (__EMSCRIPTEN__).
// The shaders are written once, as `#version 450 core`; preprocess_shader (shader.hpp) rewrites
// their header for the build's profile and moves their `layout(binding = N)` to the host.
#pragma once

namespace ocean {

enum class GlProfile { Core45, Core41, Es30 };

#if defined(__EMSCRIPTEN__) || defined(OCEAN_GL_ES)
inline constexpr GlProfile kBuildProfile = GlProfile::Es30;
#elif defined(OCEAN_GL_PORTABLE)
inline constexpr GlProfile kBuildProfile = GlProfile::Core41;
#else
inline constexpr GlProfile kBuildProfile = GlProfile::Core45;
#endif

// The context a build asks for: 4.5 or 4.1 core, or ES 3.0 (a driver may give a later version).
inline constexpr bool kBuildIsEs = kBuildProfile == GlProfile::Es30;
inline constexpr int kBuildGlMajor = kBuildIsEs ? 3 : 4;
inline constexpr int kBuildGlMinor = kBuildProfile == GlProfile::Core45 ? 5 : kBuildIsEs ? 0 : 1;

// "4.5 core", "4.1 core", "ES 3.0": for messages.
constexpr const char* profile_name(GlProfile profile) {
    return profile == GlProfile::Core45 ? "4.5 core" : profile == GlProfile::Core41 ? "4.1 core" : "ES 3.0";
}

}  // namespace ocean
