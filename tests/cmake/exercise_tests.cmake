# exercise_tests: the exercise tool (exercises/) takes bad input and misbehaving learner code
# without a hang, a crash or a command run from a name. Every test is labelled bad_input and tools
# (and gpu where it makes a GL context).

# The command line and the check program's output as the pure parsers read them
# (tests/unit/test_exercise_input.cpp), run as tools.exercise_input.<suite>.<test>.
add_executable(exercise_input_tests unit/test_exercise_input.cpp)
target_link_libraries(exercise_input_tests PRIVATE exercise_input GTest::gtest_main)
ocean_warnings(exercise_input_tests)
ocean_gtests(exercise_input_tests "tools.exercise_input." LABELS bad_input tools LEAK_CHECK)

# Every bad command line we know of, from one table (tests/cli/exercise_catalogue.sh): one
# "exercise: error: " line, a non-zero exit, no file written, no command run from a quote.
add_test(NAME tools.exercise_catalogue
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/exercise_catalogue.sh" $<TARGET_FILE:exercise>
          "${CMAKE_BINARY_DIR}/test-output/exercise_catalogue")
set_tests_properties(tools.exercise_catalogue PROPERTIES LABELS "bad_input;tools" TIMEOUT 300)

# A learner's C++ (step07's exercise 2) that loops for ever, prints a NaN, an infinity, too few or
# too many values or lines, garbage, or for ever, aborts or exits 3; one that lives in a folder
# whose name holds a quote; a GLSL function (step01's exercise 1) whose loop does not end: each gets
# its own one-line verdict, within its time limit (tests/cli/exercise_programs.sh). And a GLSL check
# whose shader file cannot be written: the tool's one error line, from the child that ran the check.
foreach(case endless_loop nan infinite too_few_values too_many_values too_few_lines extra_line garbage abort
             exit_status print_forever quote_in_work_folder)
  add_test(NAME tools.exercise_program.${case}
    COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/exercise_programs.sh" $<TARGET_FILE:exercise> "${PROJECT_SOURCE_DIR}"
            "${CMAKE_BINARY_DIR}/test-output/exercise_program/${case}" ${case})
  set_tests_properties(tools.exercise_program.${case} PROPERTIES LABELS "bad_input;tools" TIMEOUT 300)
endforeach()
foreach(case glsl_endless_loop unwritable_check_file)
  add_test(NAME tools.exercise_program.${case}
    COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/exercise_programs.sh" $<TARGET_FILE:exercise> "${PROJECT_SOURCE_DIR}"
            "${CMAKE_BINARY_DIR}/test-output/exercise_program/${case}" ${case})
  set_tests_properties(tools.exercise_program.${case} PROPERTIES LABELS "bad_input;tools;gpu" TIMEOUT 300)
endforeach()
# It waits the limit out: shortened to 5 s (exercises/limits.hpp), which proves what 30 would.
set_tests_properties(tools.exercise_program.glsl_endless_loop PROPERTIES ENVIRONMENT "OCEAN_EXERCISE_GPU_SECONDS=5" COST 5)
