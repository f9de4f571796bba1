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
