# The portable build's tests (OCEAN_GL_PORTABLE, the `portable` preset; included from the top
# CMakeLists.txt instead of tests/): the framework's CPU tests, and for each chapter it builds
# (add_step: its CPU tests, its smoke test against the same golden as the 4.5 build within the same
# tolerance, its windowed run; its split view) the bad input every step refuses. The GPU read-back
# tests, the lab and the tools stay with the default build.
include("${PROJECT_SOURCE_DIR}/tests/cmake/framework_tests.cmake")

# The loader is GL 4.1 core's: nothing newer is declared, so a 4.5 call cannot compile here.
add_test(NAME portable.loader_is_gl41
  COMMAND bash -c "h='${CMAKE_BINARY_DIR}/glad/include/glad/gl.h'; grep -q '^#define GL_VERSION_4_1 1' \"$h\" && ! grep -q 'GL_VERSION_4_2\\|glCreateBuffers\\|glDispatchCompute' \"$h\" && echo 'ok: GL 4.1 core, nothing newer'")
set_tests_properties(portable.loader_is_gl41 PROPERTIES LABELS unit)
