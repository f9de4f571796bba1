# The checks a chapter registers in its own CMakeLists.txt, after add_step, beside the ones every
# step gets (smoke, windowed, bad input, catalogue): each test is named STEP.<kind>[.<case>] and
# labelled <kind> and STEP. The harness scripts stay in tests/ (shared by every chapter); the
# chapter's own scripts sit in STEP/tests/.

# The tiers (README "Tests"). A check of one of these kinds is in the core tier, labelled core:
# what a learner needs to trust a chapter, which `./ocean test` runs. Every other check runs under
# `./ocean test --all` and in CI.
set(OCEAN_CORE_KINDS smoke split physics picture export)
# The sanitizer build (asan) declares only the checks whose C++ ASan and UBSan can judge at a
# sensible cost: bad input and the small physics and export runs (its GPU pictures would run on
# llvmpipe thirty times slower, checking Mesa's code more than ours). Label "long" stays out.
set(OCEAN_SANITIZER_KINDS bad_input physics export)

# step_test(KIND CASE COMMAND ... [LABELS ...] [TIMEOUT s] [PROPERTIES ...]): one more test of the
# chapter whose CMakeLists.txt calls it (after add_step), registered there with the chapter:
# named STEP.KIND.CASE (STEP.KIND when CASE is ""), labelled KIND, LABELS and STEP, and core for
# the kinds above. COMMAND may use the shared harness scripts (OCEAN_TESTS_DIR) and the tools'
# targets ($<TARGET_FILE:...>).
function(step_test kind case)
  if(OCEAN_PROGRAMS_ONLY)
    return()  # a programs-only build (the browser, Windows) has no ctest tests
  endif()
  cmake_parse_arguments(ARG "" "TIMEOUT" "COMMAND;LABELS;PROPERTIES" ${ARGN})
  if(NOT OCEAN_STEP)
    message(FATAL_ERROR "step_test(${kind} ${case}) outside a chapter: call add_step first")
  endif()
  if(OCEAN_SANITIZE AND (NOT kind IN_LIST OCEAN_SANITIZER_KINDS OR "long" IN_LIST ARG_LABELS))
    return()
  endif()
  set(test_name "${OCEAN_STEP}.${kind}")
  if(NOT case STREQUAL "")
    string(APPEND test_name ".${case}")
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 120)
  endif()
  set(labels ${kind} ${ARG_LABELS} ${OCEAN_STEP})
  if(kind IN_LIST OCEAN_CORE_KINDS)
    list(APPEND labels core)
  endif()
  add_test(NAME ${test_name} COMMAND ${ARG_COMMAND})
  set_tests_properties(${test_name} PROPERTIES LABELS "${labels}"
                       TIMEOUT ${ARG_TIMEOUT} ${ARG_PROPERTIES})
endfunction()

# step_figures(SOURCES... [LINKS LIBRARIES...]): the chapter's teaching figures (its figures.cpp),
# a program STEP_figures beside the step (BUILD/STEP/STEP_figures OUT_DIR writes them; its main is
# tools/figure.hpp's run_main) that ./ocean figures runs and draws with gnuplot; linked to the
# shared figure code, to the chapter's library when it has one, and to LINKS. The default build's
# only, as the tools are.
function(step_figures)
  if(OCEAN_GL_PORTABLE OR OCEAN_PROGRAMS_ONLY)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "LINKS" ${ARGN})
  set(program ${OCEAN_STEP}_figures)
  add_executable(${program} ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(${program} PRIVATE ocean_figures ${ARG_LINKS})
  if(TARGET ${OCEAN_STEP}_lib)
    target_link_libraries(${program} PRIVATE ${OCEAN_STEP}_lib)
  endif()
  ocean_warnings(${program})
endfunction()

# step_bad_input(CASE EXPECT ARGS...): the chapter's own bad input (beyond the cases every step
# gets): the step run with ARGS must exit non-zero, not crash, and print one "error:" line matching
# the regular expression EXPECT (tests/cli/bad_input.sh). Refused before any GL, so the portable
# builds leave it to the default build.
function(step_bad_input case expect)
  if(NOT OCEAN_GL_PORTABLE)
    step_refuses(${case} "${expect}" ${ARGN})
  endif()
endfunction()

# step_refuses(CASE EXPECT ARGS...): step_bad_input's test, in every build.
function(step_refuses case expect)
  if(OCEAN_PROGRAMS_ONLY)
    return()  # a programs-only build (the browser, Windows) has no ctest tests
  endif()
  step_test(bad_input ${case}
    COMMAND bash "${OCEAN_TESTS_DIR}/cli/bad_input.sh" ${case} $<TARGET_FILE:${OCEAN_STEP}>
            "${CMAKE_CURRENT_SOURCE_DIR}" "${CMAKE_BINARY_DIR}/test-output/bad_input/${OCEAN_STEP}"
            "${expect}" ${ARGN})
endfunction()

# step_broken_shader(CASE SHADER ARGS...): a copy of the chapter's shaders/ with SHADER broken,
# given as --shader-dir: the step run with ARGS must name SHADER's program and file:line in its one
# error line. For shaders the chapter's own classes load (not through the App's programs). Each
# GL profile compiles the shader its own way, so every build runs it.
function(step_broken_shader case shader)
  step_refuses(${case} ${shader} ${ARGN})
endfunction()

# step_smoke(CASE GOLDEN ARGS...): a headless run with ARGS compared with the chapter's GOLDEN
# (tests/smoke/smoke.sh), as add_step's own smoke test: STEP.smoke.CASE.
function(step_smoke case golden)
  if(OCEAN_PROGRAMS_ONLY)
    return()  # a programs-only build (the browser, Windows) has no ctest tests
  endif()
  step_test(smoke ${case} LABELS gpu TIMEOUT 300
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/smoke.sh" $<TARGET_FILE:${OCEAN_STEP}> $<TARGET_FILE:image_compare>
            "${CMAKE_CURRENT_SOURCE_DIR}/${golden}" "${CMAKE_BINARY_DIR}/test-output/smoke/${OCEAN_STEP}" ${ARGN})
endfunction()

# step_split(LEFT RIGHT [ARGS...]): --split against two plain renders of its variants, the
# parameter assignments LEFT and RIGHT (tests/smoke/split.sh, tests/split_check): STEP.split.
function(step_split left right)
  if(OCEAN_PROGRAMS_ONLY)
    return()  # a programs-only build (the browser, Windows) has no ctest tests
  endif()
  step_test(split "" LABELS gpu TIMEOUT 300
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/split.sh" $<TARGET_FILE:${OCEAN_STEP}> $<TARGET_FILE:split_check>
            "${CMAKE_BINARY_DIR}/test-output/split" "${left}" "${right}" ${ARGN})
endfunction()

# step_waves_travel(CASE DEGREES TOLERANCE ARGS...): the sea run with ARGS is exported twice, 0.1 s
# apart (t = 3 s and 3.1 s); tests/physics_check, which knows no spectrum, measures where the
# surface moved and holds it to DEGREES within TOLERANCE: STEP.physics.waves_travel_with_the_wind.CASE.
function(step_waves_travel case degrees tolerance)
  if(OCEAN_PROGRAMS_ONLY)
    return()  # a programs-only build (the browser, Windows) has no ctest tests
  endif()
  string(REPLACE ";" " " flags "${ARGN}")
  set(run "'$<TARGET_FILE:${OCEAN_STEP}>' --headless --size 64x64 ${flags}")
  set(out "${CMAKE_BINARY_DIR}/test-output/physics/${OCEAN_STEP}.${case}")
  step_test(physics waves_travel_with_the_wind.${case} LABELS gpu
    COMMAND bash -c "rm -rf '${out}' && mkdir -p '${out}' && ${run} --frames 2 --time 3 --export '${out}/a' > /dev/null && ${run} --frames 2 --time 3.1 --export '${out}/b' > /dev/null && '$<TARGET_FILE:physics_check>' travel '${out}/a' '${out}/b' ${degrees} ${tolerance}")
endfunction()
