# Windows with Visual Studio and vcpkg (vcpkg.json, the windows-msvc preset): Dependencies.cmake's
# targets made from vcpkg's packages, which come as CMake packages, not pkg-config files. Written
# for MSVC and vcpkg's ports as documented; not built on this project's Linux machines (the Windows
# build checked there is the mingw-w64 cross-build: docs/portability.md).
if(NOT OCEAN_PROGRAMS_ONLY)
  message(FATAL_ERROR "the test suite's harness (bash scripts, Xvfb) does not run on Windows yet: configure "
                      "with -DOCEAN_PROGRAMS_ONLY=ON (the windows-msvc preset does)")
endif()
find_package(glfw3 CONFIG REQUIRED)   # glfw
find_package(glm CONFIG REQUIRED)     # glm::glm
find_package(imgui CONFIG REQUIRED)   # imgui::imgui, the GLFW and OpenGL 3 bindings compiled in
find_package(Stb REQUIRED)            # Stb_INCLUDE_DIR: headers only
find_package(Threads REQUIRED)
find_program(GLAD_EXECUTABLE glad REQUIRED)  # pip install glad2

# vcpkg puts ImGui's backend headers beside imgui.h; the code includes them as Debian installs
# them, <backends/...>: two forwarding headers give that path.
foreach(_backend imgui_impl_glfw imgui_impl_opengl3)
  file(WRITE "${CMAKE_BINARY_DIR}/imgui_backends/backends/${_backend}.h" "#pragma once\n#include <${_backend}.h>\n")
endforeach()
add_library(ocean_imgui INTERFACE)
target_include_directories(ocean_imgui SYSTEM INTERFACE "${CMAKE_BINARY_DIR}/imgui_backends")
target_link_libraries(ocean_imgui INTERFACE imgui::imgui glfw)

add_library(ocean_stb STATIC "${PROJECT_SOURCE_DIR}/web/stb.c")  # vcpkg's stb is headers only
target_include_directories(ocean_stb SYSTEM PUBLIC "${Stb_INCLUDE_DIR}")
add_library(PkgConfig::STB INTERFACE IMPORTED GLOBAL)
target_link_libraries(PkgConfig::STB INTERFACE ocean_stb)

# FFTW through vcpkg's fftw3 (its threads feature builds the threads into the library itself).
if(OCEAN_FFTW)
  find_package(FFTW3 CONFIG REQUIRED)
  find_package(FFTW3f CONFIG REQUIRED)
  add_library(PkgConfig::FFTW INTERFACE IMPORTED GLOBAL)
  target_link_libraries(PkgConfig::FFTW INTERFACE FFTW3::fftw3)
  add_library(PkgConfig::FFTWF INTERFACE IMPORTED GLOBAL)
  target_link_libraries(PkgConfig::FFTWF INTERFACE FFTW3::fftw3f)
  set(FFTWF_THREADS "")
endif()
set(OCEAN_EGL OFF)  # Windows has no EGL: headless runs open a hidden window
