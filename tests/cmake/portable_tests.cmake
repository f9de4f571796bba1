# The portable build's tests (OCEAN_GL_PORTABLE, the `portable` and `es` presets; included from the
# top CMakeLists.txt instead of tests/): what the GL profile changes. For each chapter it builds
# (add_step: its smoke test against the same golden as the 4.5 build within the same tolerance, its
# windowed run; its split view and pictures) a broken shader, the fragment passes that stand in for
# compute shaders, and the loader's profile. The CPU tests (no profile changes their results), the
# GPU read-back tests (GL 4.5 calls), the lab and the tools stay with the default build.
include("${PROJECT_SOURCE_DIR}/tests/cmake/framework_tests.cmake")

if(OCEAN_GL_ES)
  # The loader is OpenGL ES 3.0's: nothing from ES 3.1 or desktop GL is declared, so a call outside
  # WebGL 2's profile (compute, glProgramUniform, glPolygonMode, multi-draws) cannot compile here.
  add_test(NAME es.loader_is_gles30
    COMMAND bash -c "h='${CMAKE_BINARY_DIR}/glad/include/glad/gles2.h'; grep -q '^#define GL_ES_VERSION_3_0 1' \"$h\" && ! grep -q 'GL_ES_VERSION_3_1\\|glDispatchCompute\\|glProgramUniform\\|glPolygonMode\\|glMultiDrawElements\\|GL_TIME_ELAPSED ' \"$h\" && echo 'ok: OpenGL ES 3.0, nothing newer'")
  set_tests_properties(es.loader_is_gles30 PROPERTIES LABELS "profile;core")
else()
  # The loader is GL 4.1 core's: nothing newer is declared, so a 4.5 call cannot compile here.
  add_test(NAME portable.loader_is_gl41
    COMMAND bash -c "h='${CMAKE_BINARY_DIR}/glad/include/glad/gl.h'; grep -q '^#define GL_VERSION_4_1 1' \"$h\" && ! grep -q 'GL_VERSION_4_2\\|glCreateBuffers\\|glDispatchCompute' \"$h\" && echo 'ok: GL 4.1 core, nothing newer'")
  set_tests_properties(portable.loader_is_gl41 PROPERTIES LABELS "profile;core")
endif()

if(NOT OCEAN_EGL)
  # Built as a Mac builds (no EGL): the loader has no EGL part, a headless run says it draws in a
  # hidden GLFW window (the first line, under the Xvfb ./ocean starts), and without a display a
  # headless run says in one line what it needs.
  add_test(NAME portable.headless_without_egl
    COMMAND bash -c "! test -e '${CMAKE_BINARY_DIR}/glad/include/glad/egl.h' && out=$('$<TARGET_FILE:step01_sine2d>' --headless --frames 1 2>&1) && echo \"$out\" | head -n 1 | grep -q '(hidden GLFW window' && echo 'ok: no EGL loader; headless in a hidden GLFW window'")
  set_tests_properties(portable.headless_without_egl PROPERTIES LABELS "profile;core")
  add_test(NAME portable.headless_without_egl_needs_a_display
    COMMAND bash -c "out=$(env -u DISPLAY -u WAYLAND_DISPLAY '$<TARGET_FILE:step01_sine2d>' --headless --frames 1 2>&1 >/dev/null); status=$?; echo \"$out\"; [ $status -eq 1 ] && [ $(echo \"$out\" | grep -c '') -eq 1 ] && echo \"$out\" | grep -q 'no EGL: its headless runs need a display'")
  set_tests_properties(portable.headless_without_egl_needs_a_display PROPERTIES LABELS "profile;bad_input")
endif()
