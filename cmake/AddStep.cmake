# add_step(NAME SOURCES ... [LIBRARY ...] SHADERS ... [LINKS ...] [TESTS ...] [GOLDEN file])
# declares one chapter:
#  - the executable NAME (folder, target and window title share the name),
#  - with LIBRARY, a static library NAME_lib of the chapter's technique, which the step, the
#    tests and later chapters link (step06 links step05_fft_lib),
#  - its shaders and README listed in the target (IDEs show them; shaders are read from the
#    source tree at run time, so edits hot-reload),
#  - with TESTS, the chapter's own GoogleTest files, built into NAME_tests (linked with NAME_lib
#    and, for tests that need GL, tests/gpu's headless context helpers) and run by ctest as
#    NAME.<suite>.<test>, labelled unit,
#  - its smoke test: a headless run compared with GOLDEN (default tests/smoke/golden/NAME.png),
#  - its windowed run under Xvfb,
#  - its entry in the lists the shader, bad-input and catalogue tests walk (OCEAN_STEPS,
#    OCEAN_SHADERS).
# A new chapter needs nothing else: the top CMakeLists.txt finds the folder (see "Adding a
# chapter" in the README, and step_template/).
include(GoogleTest)
set(OCEAN_TESTS_DIR "${CMAKE_CURRENT_LIST_DIR}/../tests")

function(add_step name)
  cmake_parse_arguments(ARG "" "GOLDEN" "SOURCES;LIBRARY;SHADERS;LINKS;TESTS" ${ARGN})
  list(TRANSFORM ARG_SHADERS PREPEND "${CMAKE_CURRENT_SOURCE_DIR}/")
  add_executable(${name} ${ARG_SOURCES} ${ARG_SHADERS} README.md)
  target_link_libraries(${name} PRIVATE ocean_common ${ARG_LINKS})
  if(ARG_LIBRARY)
    add_library(${name}_lib STATIC ${ARG_LIBRARY})
    target_link_libraries(${name}_lib PUBLIC ocean_common ${ARG_LINKS})
    target_include_directories(${name}_lib PUBLIC "${PROJECT_SOURCE_DIR}")
    ocean_warnings(${name}_lib)
    target_link_libraries(${name} PRIVATE ${name}_lib)
  endif()
  target_include_directories(${name} PRIVATE "${PROJECT_SOURCE_DIR}")
  target_compile_definitions(${name} PRIVATE
    OCEAN_STEP_NAME="${name}" OCEAN_STEP_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
  ocean_warnings(${name})

  if(ARG_TESTS)
    add_executable(${name}_tests ${ARG_TESTS})
    target_link_libraries(${name}_tests PRIVATE ocean_common GTest::gtest_main)
    if(ARG_LIBRARY)
      target_link_libraries(${name}_tests PRIVATE ${name}_lib)
    endif()
    target_include_directories(${name}_tests PRIVATE "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
    target_compile_definitions(${name}_tests PRIVATE OCEAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
      OCEAN_STEP_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
    ocean_warnings(${name}_tests)
    gtest_discover_tests(${name}_tests TEST_PREFIX "${name}." PROPERTIES LABELS unit DISCOVERY_TIMEOUT 60)
  endif()

  set_property(GLOBAL APPEND PROPERTY OCEAN_STEPS ${name})
  set_property(GLOBAL APPEND PROPERTY OCEAN_SHADERS ${ARG_SHADERS})

  set(golden "${OCEAN_TESTS_DIR}/smoke/golden/${name}.png")
  if(ARG_GOLDEN)
    set(golden "${CMAKE_CURRENT_SOURCE_DIR}/${ARG_GOLDEN}")
  endif()
  add_test(NAME smoke.${name}
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/smoke.sh" $<TARGET_FILE:${name}>
            $<TARGET_FILE:image_compare> "${golden}" "${CMAKE_BINARY_DIR}/test-output/smoke")
  set_tests_properties(smoke.${name} PROPERTIES LABELS "smoke;gpu" TIMEOUT 300)

  add_test(NAME windowed.${name}
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/windowed.sh" $<TARGET_FILE:${name}>)
  # RESOURCE_LOCK: two `xvfb-run -a` starting at once can race for the same display number.
  set_tests_properties(windowed.${name} PROPERTIES LABELS "windowed;gpu" TIMEOUT 300 RESOURCE_LOCK xvfb
    SKIP_RETURN_CODE 77)
endfunction()
