# The libraries some builds compile from source: Dear ImGui 1.86 (the browser, the Windows
# cross-build, macOS), stb (the Windows cross-build, macOS) and GLFW 3.3.8 (the Windows
# cross-build). ./ocean fetches each into build/sources/NAME and checks it (tools/source_archives.sh:
# Debian's source archive through apt-get source, or upstream's on macOS; then every file compiled
# against tools/sources/NAME.sha256); a tree it checked holds a file named .checked.
set(OCEAN_SOURCES_DIR "${PROJECT_SOURCE_DIR}/build/sources" CACHE PATH "Where ./ocean puts the checked source trees")

# ocean_source_tree(NAME VAR): VAR = the checked tree of NAME, or a one-line configure error.
function(ocean_source_tree name var)
  set(dir "${OCEAN_SOURCES_DIR}/${name}")
  if(NOT EXISTS "${dir}/.checked")
    message(FATAL_ERROR "this build compiles ${name} from its source, which is not in ${OCEAN_SOURCES_DIR}: "
                        "./ocean fetches and checks it (tools/source_archives.sh)")
  endif()
  set(${var} "${dir}" PARENT_SCOPE)
endfunction()

# ocean_imgui: ImGui with its GLFW and OpenGL 3 backends (ES3: the backend's OpenGL ES 3 form).
function(ocean_imgui_from_source)
  cmake_parse_arguments(ARG "ES3" "" "" ${ARGN})
  ocean_source_tree(imgui-1.86 dir)
  add_library(ocean_imgui STATIC
    "${dir}/imgui.cpp" "${dir}/imgui_draw.cpp" "${dir}/imgui_tables.cpp" "${dir}/imgui_widgets.cpp"
    "${dir}/backends/imgui_impl_glfw.cpp" "${dir}/backends/imgui_impl_opengl3.cpp")
  if(ARG_ES3)
    target_compile_definitions(ocean_imgui PRIVATE IMGUI_IMPL_OPENGL_ES3)
  endif()
  # <imgui.h>, and <backends/imgui_impl_opengl3.h> as Debian installs them.
  target_include_directories(ocean_imgui SYSTEM PUBLIC "${dir}")
  target_link_libraries(ocean_imgui PUBLIC glfw)
  set(OCEAN_IMGUI_LICENCE "${dir}/LICENSE.txt" PARENT_SCOPE)
endfunction()

# PkgConfig::STB, as Debian's libstb gives it: the headers, and the implementations of the two the
# framework uses (stb_image, stb_image_write) compiled once (web/stb.c).
function(ocean_stb_from_source)
  ocean_source_tree(stb-8b5f1f3 dir)
  add_library(ocean_stb STATIC "${PROJECT_SOURCE_DIR}/web/stb.c")
  target_include_directories(ocean_stb SYSTEM PUBLIC "${dir}")
  add_library(PkgConfig::STB INTERFACE IMPORTED GLOBAL)
  target_link_libraries(PkgConfig::STB INTERFACE ocean_stb)
endfunction()

# ocean_host_headers(LIB): the host's /usr/include/LIB (a header-only library from its Debian
# package) linked alone into BUILD/host_headers, so a cross-compiler sees that folder, not the
# host's whole /usr/include.
function(ocean_host_headers lib)
  if(NOT EXISTS "/usr/include/${lib}")
    message(FATAL_ERROR "this build reads ${lib}'s headers from /usr/include/${lib} (install lib${lib}-dev)")
  endif()
  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/host_headers")
  file(CREATE_LINK "/usr/include/${lib}" "${CMAKE_BINARY_DIR}/host_headers/${lib}" SYMBOLIC)
endfunction()

# glm::glm from the host's libglm-dev (header-only: the same on every platform).
function(ocean_glm_from_host)
  ocean_host_headers(glm)
  add_library(glm::glm INTERFACE IMPORTED GLOBAL)
  target_include_directories(glm::glm SYSTEM INTERFACE "${CMAKE_BINARY_DIR}/host_headers")
endfunction()
