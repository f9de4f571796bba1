# ocean_gtests(TARGET PREFIX LABELS label... [LEAK_CHECK]): the GoogleTest executable TARGET's tests,
# found when it is built (gtest_discover_tests), named PREFIX<suite>.<test> and labelled with every
# LABELS (a kind, a chapter, the tier: core). gtest_discover_tests cannot pass a list of labels
# through (its PROPERTIES split on ';'), so a script ctest reads after the discovered tests sets
# them. LEAK_CHECK: LeakSanitizer checks them in the sanitizer build (CPU-only tests: where GL runs,
# llvmpipe's JIT-compiled code and unloaded drivers leave allocations it cannot even name).
include(GoogleTest)

function(ocean_gtests target prefix)
  cmake_parse_arguments(ARG "LEAK_CHECK" "" "LABELS" ${ARGN})
  set(properties "")
  if(ARG_LEAK_CHECK)
    set(properties PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1")
  endif()
  gtest_discover_tests(${target} TEST_PREFIX "${prefix}" TEST_LIST ${target}_list DISCOVERY_TIMEOUT 60 ${properties})
  set(label_script "${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake")
  file(WRITE "${label_script}"
       "if(${target}_list)\n  set_tests_properties(\${${target}_list} PROPERTIES LABELS \"${ARG_LABELS}\")\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${label_script}")
endfunction()

# ocean_sanitizer_skips(TARGET TEST...): in the sanitizer build, these tests that ocean_gtests found
# in TARGET (full names, as ctest lists them) are not run: unit tests that run the chapter's code for long simulated times
# (tens of seconds each under ASan), each beside a shorter test of the same suite that takes the
# same code through ASan and UBSan. The default builds run them all. Called in the chapter's
# CMakeLists.txt after add_step (ctest reads this script after the discovered tests).
function(ocean_sanitizer_skips target)
  if(NOT OCEAN_SANITIZE)
    return()
  endif()
  set(script "${CMAKE_CURRENT_BINARY_DIR}/${target}_sanitizer_skips.cmake")
  set(lines "")
  foreach(test ${ARGN})
    # (list(FIND): ctest's scripts run without CMake's newer policies, IN_LIST among them)
    string(APPEND lines "list(FIND ${target}_list \"${test}\" found)\n"
                        "if(NOT found EQUAL -1)\n  set_tests_properties(\"${test}\" PROPERTIES DISABLED TRUE)\nendif()\n")
  endforeach()
  file(WRITE "${script}" "${lines}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${script}")
endfunction()
