# add_step(NAME SOURCES ... [LIBRARY ...] SHADERS ...) declares one chapter:
#  - the executable NAME (folder, target and window title share the name),
#  - with LIBRARY, a static library NAME_lib of the chapter's technique, which the step, the
#    tests and later chapters link (step06 links step05_fft_lib),
#  - its shaders and README listed in the target (IDEs show them; shaders are read from the
#    source tree at run time, so edits hot-reload),
#  - its smoke test (headless run compared with tests/smoke/golden/NAME.png),
#  - its windowed run under Xvfb,
#  - its entry in the lists the shader tests walk (OCEAN_STEPS, OCEAN_SHADERS).
set(OCEAN_TESTS_DIR "${CMAKE_CURRENT_LIST_DIR}/../tests")

function(add_step name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARY;SHADERS;LINKS" ${ARGN})
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

  set_property(GLOBAL APPEND PROPERTY OCEAN_STEPS ${name})
  set_property(GLOBAL APPEND PROPERTY OCEAN_SHADERS ${ARG_SHADERS})

  add_test(NAME smoke.${name}
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/smoke.sh" $<TARGET_FILE:${name}>
            $<TARGET_FILE:image_compare> "${OCEAN_TESTS_DIR}/smoke/golden/${name}.png"
            "${CMAKE_BINARY_DIR}/test-output/smoke")
  set_tests_properties(smoke.${name} PROPERTIES LABELS "smoke;gpu" TIMEOUT 300)

  add_test(NAME windowed.${name}
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/windowed.sh" $<TARGET_FILE:${name}>)
  # RESOURCE_LOCK: two `xvfb-run -a` starting at once can race for the same display number.
  set_tests_properties(windowed.${name} PROPERTIES LABELS "windowed;gpu" TIMEOUT 300 RESOURCE_LOCK xvfb
    SKIP_RETURN_CODE 77)
endfunction()
