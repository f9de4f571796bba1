# The browser build (./ocean web: emscripten's toolchain, WebGL 2 = OpenGL ES 3.0). It stands in for
# Dependencies.cmake and Glad.cmake: the same target names, made from what emscripten brings (its
# GLFW, its GLES 3 headers), the host's header-only libraries (glm, stb), and Dear ImGui 1.86
# compiled from Debian's own source tarball, the version the native build links (its MIT licence,
# LICENSE.txt, is served beside the pages). No FFTW, no GPL code: the web build is under the
# project's licence and ImGui's.
set(OCEAN_WEB_DIR "${CMAKE_BINARY_DIR}/web_deps")

# glm and stb are header-only: their folders, not the host's whole /usr/include.
file(MAKE_DIRECTORY "${OCEAN_WEB_DIR}/host")
foreach(_lib glm stb)
  if(NOT EXISTS "/usr/include/${_lib}")
    message(FATAL_ERROR "the web build reads ${_lib}'s headers from /usr/include/${_lib} (install lib${_lib}-dev)")
  endif()
  file(CREATE_LINK "/usr/include/${_lib}" "${OCEAN_WEB_DIR}/host/${_lib}" SYMBOLIC)
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE "${OCEAN_WEB_DIR}/host")
add_library(ocean_stb STATIC "${PROJECT_SOURCE_DIR}/web/stb.c")  # the implementations libstb holds natively
target_include_directories(ocean_stb SYSTEM PUBLIC "${OCEAN_WEB_DIR}/host/stb")
add_library(PkgConfig::STB INTERFACE IMPORTED)
target_link_libraries(PkgConfig::STB INTERFACE ocean_stb)

# GLFW and the GL: emscripten's own, chosen at link time.
add_library(glfw INTERFACE)
target_link_options(glfw INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)
add_library(glad INTERFACE)  # no loader: <GLES3/gl3.h> declares what WebGL 2 has
target_compile_definitions(glad INTERFACE OCEAN_GL_PORTABLE OCEAN_GL_ES)

# Dear ImGui 1.86 from Debian's source tarball (the +ds tarball keeps the sources, the backends and
# the licence), checked against its hash; ./ocean web downloads it into this folder.
set(OCEAN_IMGUI_TARBALL "${OCEAN_WEB_DIR}/imgui_1.86+ds.orig.tar.xz")
set(OCEAN_IMGUI_SHA256 0dace0e8e57d298eb6e93af12dc19420cb96330832f6495c733b90aeeef11f64)
set(OCEAN_IMGUI_DIR "${OCEAN_WEB_DIR}/imgui-1.86")
if(NOT EXISTS "${OCEAN_IMGUI_DIR}/imgui.cpp")
  if(NOT EXISTS "${OCEAN_IMGUI_TARBALL}")
    message(FATAL_ERROR "the web build needs Dear ImGui 1.86's sources: ${OCEAN_IMGUI_TARBALL} "
                        "(./ocean web downloads it from Debian's archive)")
  endif()
  file(SHA256 "${OCEAN_IMGUI_TARBALL}" _imgui_hash)
  if(NOT _imgui_hash STREQUAL OCEAN_IMGUI_SHA256)
    message(FATAL_ERROR "${OCEAN_IMGUI_TARBALL} is not Debian's imgui 1.86+ds tarball (sha256 ${_imgui_hash})")
  endif()
  file(ARCHIVE_EXTRACT INPUT "${OCEAN_IMGUI_TARBALL}" DESTINATION "${OCEAN_WEB_DIR}")
endif()
add_library(ocean_imgui STATIC
  "${OCEAN_IMGUI_DIR}/imgui.cpp" "${OCEAN_IMGUI_DIR}/imgui_draw.cpp" "${OCEAN_IMGUI_DIR}/imgui_tables.cpp"
  "${OCEAN_IMGUI_DIR}/imgui_widgets.cpp" "${OCEAN_IMGUI_DIR}/backends/imgui_impl_glfw.cpp"
  "${OCEAN_IMGUI_DIR}/backends/imgui_impl_opengl3.cpp")
target_compile_definitions(ocean_imgui PRIVATE IMGUI_IMPL_OPENGL_ES3)
target_include_directories(ocean_imgui SYSTEM PUBLIC "${OCEAN_IMGUI_DIR}")
target_link_libraries(ocean_imgui PUBLIC glfw)

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
