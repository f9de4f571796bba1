# Every dependency is a Debian package; ./ocean installs the missing ones (see its PACKAGES list).
# On macOS they come from Homebrew (./ocean names them), except Dear ImGui 1.86 and stb, which it
# has not: there they are compiled from their checked sources (cmake/SourceTrees.cmake).
include(SourceTrees)
option(OCEAN_FFTW "The CPU FFT through FFTW; OFF: the chapter's own radix 2" ON)
if(VCPKG_TOOLCHAIN)
  include(VcpkgDependencies)  # Windows with Visual Studio: vcpkg's CMake packages
  return()
endif()
find_package(glfw3 3.3 REQUIRED)          # libglfw3-dev: windows, input
find_package(glm REQUIRED)                # libglm-dev: vectors and matrices
find_package(PkgConfig REQUIRED)
pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)  # libimgui-dev 1.86, backends included
pkg_check_modules(STB QUIET IMPORTED_TARGET stb)      # libstb-dev: stb_image, stb_image_write
if(NOT STB_FOUND)
  ocean_stb_from_source()
endif()
# Headless runs: EGL where the system has it (libegl-dev), a hidden GLFW window where it has none
# (macOS, Windows) or where OCEAN_EGL is turned off (the CI's portable pass, as a Mac builds).
pkg_check_modules(EGL QUIET IMPORTED_TARGET egl)
option(OCEAN_EGL "Headless runs through EGL; OFF: through a hidden GLFW window (needs a display)" ${EGL_FOUND})
if(OCEAN_EGL AND NOT EGL_FOUND)
  message(FATAL_ERROR "OCEAN_EGL is ON but pkg-config finds no egl (install libegl-dev, or configure with -DOCEAN_EGL=OFF)")
endif()
if(NOT OCEAN_EGL)
  message(STATUS "Headless runs: a hidden GLFW window (no EGL)")
endif()
if(NOT OCEAN_PROGRAMS_ONLY)
  find_package(GTest REQUIRED)            # libgtest-dev
endif()

find_program(GLAD_EXECUTABLE glad REQUIRED)              # python3-glad
find_program(GLSLANG_VALIDATOR glslangValidator)         # glslang-tools (a test, optional to build)
find_program(XVFB_RUN xvfb-run)                          # xvfb (windowed tests, optional)

# imgui.a holds the GLFW and OpenGL3 backends, which call into GLFW.
if(NOT IMGUI_FOUND)
  if(OCEAN_GL_ES)
    message(FATAL_ERROR "the ES build takes ImGui's ES backend from libimgui-dev (Debian/Ubuntu)")
  endif()
  ocean_imgui_from_source()
else()
add_library(ocean_imgui INTERFACE)
if(OCEAN_GL_ES)
  # imgui.a's OpenGL3 backend is built for desktop GL (glPolygonMode, primitive restart): an ES
  # context refuses those calls. The ES build compiles the same backend from the package's copy of
  # its source, in its ES 3 form, through our loader (the shim's GLES3/gl3.h is glad's gles2.h); the
  # linker then takes the backend from here (named first) and the rest of ImGui from imgui.a.
  find_file(IMGUI_OPENGL3_SOURCE imgui_impl_opengl3.cpp
            PATHS /usr/share/doc/libimgui-dev/examples/backends NO_DEFAULT_PATH)
  if(NOT IMGUI_OPENGL3_SOURCE)
    message(FATAL_ERROR "the ES build needs ImGui's OpenGL3 backend source, which libimgui-dev installs "
                        "as /usr/share/doc/libimgui-dev/examples/backends/imgui_impl_opengl3.cpp "
                        "(reinstall libimgui-dev where /usr/share/doc is excluded)")
  endif()
  file(WRITE "${CMAKE_BINARY_DIR}/imgui_es/GLES3/gl3.h"
       "// ImGui's ES 3 backend includes this: GL ES 3.0 through the build's loader.\n#include <glad/gles2.h>\n")
  add_library(ocean_imgui_es_renderer STATIC "${IMGUI_OPENGL3_SOURCE}")
  target_compile_definitions(ocean_imgui_es_renderer PRIVATE IMGUI_IMPL_OPENGL_ES3)
  target_include_directories(ocean_imgui_es_renderer SYSTEM PRIVATE "${CMAKE_BINARY_DIR}/imgui_es"
                             /usr/include/imgui/backends)
  target_link_libraries(ocean_imgui_es_renderer PUBLIC PkgConfig::IMGUI glad)
  target_link_libraries(ocean_imgui INTERFACE ocean_imgui_es_renderer)
endif()
target_link_libraries(ocean_imgui INTERFACE PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})
endif()
# libfftw3-dev: the CPU FFT (step05) in double, in single precision and its threads (the FFTW
# backend, the benchmark's floor). Without it (-DOCEAN_FFTW=OFF) step05 runs its own radix 2.
if(OCEAN_FFTW)
  pkg_check_modules(FFTW REQUIRED IMPORTED_TARGET fftw3)
  pkg_check_modules(FFTWF REQUIRED IMPORTED_TARGET fftw3f)
  find_library(FFTWF_THREADS fftw3f_threads REQUIRED)
endif()
find_package(Threads REQUIRED)
# libwebp-dev: tools/animate encodes the READMEs' animations (animated WebP, WebPAnimEncoder) and
# reads them back (WebPAnimDecoder) to check them.
if(NOT OCEAN_PROGRAMS_ONLY)
  pkg_check_modules(WEBP REQUIRED IMPORTED_TARGET libwebpmux libwebpdemux libwebp)
endif()
