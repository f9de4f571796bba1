# Every parameter of every step at the two ends of the range --list-params prints: accepted, and
# saved back as that value (tests/cli/param_ends.sh). No GL: --save-preset exits before a context.
foreach(step IN LISTS OCEAN_STEPS)
  add_test(NAME ${step}.param_ends
    COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/param_ends.sh" $<TARGET_FILE:${step}>
            "${CMAKE_BINARY_DIR}/test-output/param_ends/${step}")
  set_tests_properties(${step}.param_ends PROPERTIES LABELS "bad_input;${step}" TIMEOUT 120)
endforeach()
