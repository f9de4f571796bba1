# The browser build (./ocean web: emscripten's toolchain, WebGL 2 = OpenGL ES 3.0). It stands in for
# Dependencies.cmake and Glad.cmake: the same target names, made from what emscripten brings (its
# GLFW, its GLES 3 headers), the host's header-only libraries (glm, stb), and Dear ImGui 1.86
# compiled from Debian's own source tarball, the version the native build links (its MIT licence,
# LICENSE.txt, is served beside the pages). No FFTW, no GPL code: the web build is under the
# project's licence and ImGui's.
# glm and stb are header-only: glm's folder from the host, stb's from the host's libstb-dev.
include(SourceTrees)
ocean_glm_from_host()
ocean_host_headers(stb)
add_library(ocean_stb STATIC "${PROJECT_SOURCE_DIR}/web/stb.c")  # the implementations libstb holds natively
target_include_directories(ocean_stb SYSTEM PUBLIC "${CMAKE_BINARY_DIR}/host_headers/stb")
add_library(PkgConfig::STB INTERFACE IMPORTED)
target_link_libraries(PkgConfig::STB INTERFACE ocean_stb)

# GLFW and the GL: emscripten's own, chosen at link time.
add_library(glfw INTERFACE)
target_link_options(glfw INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)
add_library(glad INTERFACE)  # no loader: <GLES3/gl3.h> declares what WebGL 2 has
target_compile_definitions(glad INTERFACE OCEAN_GL_PORTABLE OCEAN_GL_ES)

# Dear ImGui 1.86 from Debian's source tarball (./ocean web fetches it with apt-get source and checks
# it: cmake/SourceTrees.cmake), in its OpenGL ES 3 form; its licence is served beside the pages.
ocean_imgui_from_source(ES3)
configure_file("${OCEAN_IMGUI_LICENCE}" "${CMAKE_BINARY_DIR}/site/imgui-LICENSE.txt" COPYONLY)

# Every page: exceptions caught as natively; the browser calls the frame loop a frame at a time
# (App::browser_frame, through emscripten_set_main_loop: no Asyncify, whose rewrite of every
# function made the links slow and the pages slower), the memory grows as a chapter needs, and the
# shaders are in the page's file system at the paths the native build reads them from (add_step
# preloads each chapter's).
# C++ exceptions on (emscripten leaves them off by default): the framework reports errors by them.
add_compile_options(-fexceptions)
add_link_options(-fexceptions -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1
                 -sEXPORTED_RUNTIME_METHODS=FS  # tests/web/page.js reads a screenshot from the page's files
                 "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/common/shaders@${PROJECT_SOURCE_DIR}/common/shaders")
