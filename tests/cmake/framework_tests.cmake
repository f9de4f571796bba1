# What the default build and the portable ones (portable_tests.cmake) both declare: image_compare
# (every smoke test), split_check (each chapter's step_split), the framework's CPU unit tests (not
# in the portable builds: no GL profile changes them), the fragment passes' GPU tests (not in the
# sanitizer build), and the bad input every chapter refuses (in the portable builds, only the
# broken shader: the others are refused before any GL).
set(_tests "${PROJECT_SOURCE_DIR}/tests")

# image_compare: compares a screenshot with its golden image (used by every smoke test).
add_executable(image_compare "${_tests}/image_compare.cpp")
target_link_libraries(image_compare PRIVATE ocean_common)
ocean_warnings(image_compare)

# unit: the framework on the CPU (each chapter's own math is tested in its folder: add_step TESTS).
if(NOT OCEAN_GL_PORTABLE)
  set(_unit test_params test_cli test_image test_grid test_shader_source test_frame_clock test_faster_of_two
            test_file_output test_input_events test_input_hand_over test_panel_groups test_panel_state
            test_panel_widgets)
  list(TRANSFORM _unit PREPEND "${_tests}/unit/")
  list(TRANSFORM _unit APPEND ".cpp")
  add_executable(unit_tests ${_unit})
  target_link_libraries(unit_tests PRIVATE ocean_common GTest::gtest_main)
  target_include_directories(unit_tests PRIVATE "${PROJECT_SOURCE_DIR}")
  target_compile_definitions(unit_tests PRIVATE OCEAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  ocean_warnings(unit_tests)
  # LeakSanitizer checks the CPU-only unit tests (the asan preset turns it off elsewhere: llvmpipe's
  # JIT-compiled code and unloaded GL drivers leave allocations it cannot even name).
  ocean_gtests(unit_tests "unit." LABELS unit core LEAK_CHECK)
endif()

# The fragment passes that stand in for compute shaders, in the build's GL profile: float textures
# (common/gl_texture.hpp), step05's fragment FFT and simulation, and step06's sky and foam, whose sources it
# compiles (they need nothing else of their chapters, which the portable builds may leave out).
if(NOT OCEAN_SANITIZE)
  add_executable(portable_gpu_tests "${_tests}/gpu/gpu_main.cpp" "${_tests}/gpu/portable_gpu.cpp"
                 "${PROJECT_SOURCE_DIR}/step05_fft/fragment_fft.cpp" "${PROJECT_SOURCE_DIR}/step05_fft/fragment_simulation.cpp"
                 "${PROJECT_SOURCE_DIR}/step06_foam_sky/sky.cpp" "${PROJECT_SOURCE_DIR}/step06_foam_sky/foam.cpp"
                 "${PROJECT_SOURCE_DIR}/step06_foam_sky/extra_waves.cpp"
                 "${PROJECT_SOURCE_DIR}/step06_foam_sky/foam_pattern.cpp")
  if(NOT OCEAN_GL_PORTABLE)
    target_sources(portable_gpu_tests PRIVATE "${PROJECT_SOURCE_DIR}/step05_fft/box_mipmaps.cpp")  # the sky's mipmaps in 4.5
  endif()
  target_link_libraries(portable_gpu_tests PRIVATE ocean_common GTest::gtest)
  target_include_directories(portable_gpu_tests PRIVATE "${PROJECT_SOURCE_DIR}")
  target_compile_definitions(portable_gpu_tests PRIVATE OCEAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  ocean_warnings(portable_gpu_tests)
  ocean_gtests(portable_gpu_tests "gpu." LABELS gpu core)

  # split_check: a --split screenshot against its two variants' renders (each chapter's step_split).
  add_executable(split_check "${_tests}/split_check.cpp")
  target_link_libraries(split_check PRIVATE ocean_common)
  ocean_warnings(split_check)
endif()

get_property(OCEAN_STEPS GLOBAL PROPERTY OCEAN_STEPS)
# bad input: each case exits non-zero with exactly one line on stderr, and no crash, in every step.
foreach(step IN LISTS OCEAN_STEPS)
  set(_cases)
  if(EXISTS "${PROJECT_SOURCE_DIR}/${step}/shaders")  # (a chapter may draw with earlier chapters' only)
    set(_cases broken_shader)
  endif()
  if(NOT OCEAN_GL_PORTABLE)
    list(APPEND _cases unknown_flag unknown_param not_a_number nan_value zero_size missing_preset malformed_preset)
  endif()
  foreach(case IN LISTS _cases)
    add_test(NAME ${step}.bad_input.${case}
      COMMAND bash "${_tests}/cli/bad_input.sh" ${case} $<TARGET_FILE:${step}>
              "${PROJECT_SOURCE_DIR}/${step}" "${CMAKE_BINARY_DIR}/test-output/bad_input/${step}")
    set_tests_properties(${step}.bad_input.${case} PROPERTIES LABELS "bad_input;${step}" TIMEOUT 120)
  endforeach()
endforeach()
