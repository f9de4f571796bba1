# The Windows cross-build (cmake/toolchains/mingw-w64.cmake, ./ocean windows) stands in for
# Dependencies.cmake, as Web.cmake does for the browser: the same target names, made from what a
# Debian machine has for Windows. GLFW 3.3.8, Dear ImGui 1.86 and stb compiled from their checked
# sources (cmake/SourceTrees.cmake), glm's headers from the host (header-only), no EGL (headless
# runs open a hidden window), no FFTW (step05's own radix 2), and the programs only: GoogleTest,
# libwebp and the test tools are not built for Windows here.
include(SourceTrees)
set(OCEAN_EGL OFF)
set(OCEAN_FFTW OFF)

ocean_source_tree(glfw-3.3.8 _glfw_dir)
set(GLFW_BUILD_DOCS OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_EXAMPLES OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(GLFW_INSTALL OFF CACHE BOOL "" FORCE)
add_subdirectory("${_glfw_dir}" "${CMAKE_BINARY_DIR}/glfw" EXCLUDE_FROM_ALL)

ocean_glm_from_host()
ocean_imgui_from_source()
ocean_stb_from_source()
find_package(Threads REQUIRED)
find_program(GLAD_EXECUTABLE glad REQUIRED)  # python3-glad, run on the host
