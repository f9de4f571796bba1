# add_step(NAME SOURCES ... [LIBRARY ...] SHADERS ... [LINKS ...] [TESTS ...] [GPU_TESTS ...]
#          [TEST_SHADERS ...] [EXERCISES ...] [GOLDEN file] [SMOKE_FLAGS ...])
# declares one step, the program of a chapter, with what it is made of and tested by:
#  - the executable NAME (folder, target and window title share the name),
#  - with LIBRARY, a static library NAME_lib of the chapter's technique, which the step, the
#    tests and later chapters link (step06 links step05_fft_lib),
#  - its shaders and README listed in the target (IDEs show them; shaders are read from the
#    source tree at run time, so edits hot-reload),
#  - with TESTS, the chapter's own GoogleTest files on the CPU, built into NAME_tests (linked with
#    NAME_lib) and run by ctest as NAME.<suite>.<test>, labelled unit, core and NAME,
#  - with GPU_TESTS, its GoogleTest files that need GL, built into NAME_gpu_tests with tests/gpu's
#    headless context (gpu_main.cpp) and run as NAME.<suite>.<test>, labelled gpu, core and NAME,
#  - with TEST_SHADERS, the shaders only its GPU tests load (in the lists every shader must pass),
#  - with EXERCISES, the chapter's exercise list (STEP/exercises.cpp), compiled into exercises/exercise,
#  - its smoke test: a headless run compared with GOLDEN (default the folder's golden.png), core,
#    with SMOKE_FLAGS given to the program (a parameter the golden picture holds still),
#  - its windowed run under Xvfb (not in the sanitizer build),
#  - OCEAN_STEP set to NAME in the chapter's CMakeLists.txt, for step_test() below,
#  - its entry in the lists the shader, bad-input and catalogue tests walk (OCEAN_STEPS,
#    OCEAN_SHADERS).
# Every test of a chapter is named STEP.<kind>[.<case>] and labelled STEP, so `ctest -L STEP` and
# `ctest -R '^STEP\.'` run the same tests (tools.test_names checks it).
# A new chapter needs nothing else: the top CMakeLists.txt finds the folder (see "Adding a
# chapter" in the README, and step_template/).
include(GoogleTests)  # ocean_gtests()
set(OCEAN_TESTS_DIR "${CMAKE_CURRENT_LIST_DIR}/../tests")

function(add_step name)
  cmake_parse_arguments(ARG "" "GOLDEN" "SOURCES;LIBRARY;SHADERS;LINKS;TESTS;GPU_TESTS;TEST_SHADERS;EXERCISES;SMOKE_FLAGS" ${ARGN})
  list(TRANSFORM ARG_SHADERS PREPEND "${CMAKE_CURRENT_SOURCE_DIR}/")
  # Every file in the chapter's shaders/ folder is listed: the shader tests walk the lists, and a
  # file left out (a shader a change stopped using, say) would never be compiled by any of them.
  file(GLOB _shaders_on_disk "${CMAKE_CURRENT_SOURCE_DIR}/shaders/*")
  foreach(file IN LISTS _shaders_on_disk)
    if(NOT file IN_LIST ARG_SHADERS)
      message(FATAL_ERROR "${name}: ${file} is in shaders/ but not in add_step's SHADERS; list it, "
                          "or delete it if nothing reads it")
    endif()
  endforeach()
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
  if(EMSCRIPTEN)
    # A page: NAME.js and NAME.wasm, with the chapter's shaders in its file system where the
    # native build reads them (tests/web, ./ocean web).
    set_target_properties(${name} PROPERTIES SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/site")
    set(STEP ${name})
    configure_file("${PROJECT_SOURCE_DIR}/web/chapter.html.in" "${CMAKE_BINARY_DIR}/site/${name}.html" @ONLY)
    # Its shaders and the earlier chapters' (a chapter's shaders include its predecessors').
    get_property(_earlier GLOBAL PROPERTY OCEAN_STEP_SOURCE_DIRS)
    foreach(_dir IN LISTS _earlier ITEMS "${CMAKE_CURRENT_SOURCE_DIR}")
      if(EXISTS "${_dir}/shaders")
        target_link_options(${name} PRIVATE "SHELL:--preload-file ${_dir}/shaders@${_dir}/shaders")
      endif()
      # And the headers the shaders include from the chapter's folder (step06's texture_units.h:
      # the one table of texture units, read by the C++ and the GLSL alike).
      file(GLOB _shared_headers "${_dir}/*.h")
      foreach(_header IN LISTS _shared_headers)
        target_link_options(${name} PRIVATE "SHELL:--preload-file ${_header}@${_header}")
      endforeach()
    endforeach()
    set_property(GLOBAL APPEND PROPERTY OCEAN_STEP_SOURCE_DIRS "${CMAKE_CURRENT_SOURCE_DIR}")
    set_property(GLOBAL APPEND PROPERTY OCEAN_STEPS ${name})
    set(OCEAN_STEP ${name} PARENT_SCOPE)
    return()
  endif()
  set(golden "${CMAKE_CURRENT_SOURCE_DIR}/golden.png")
  if(ARG_GOLDEN)
    set(golden "${CMAKE_CURRENT_SOURCE_DIR}/${ARG_GOLDEN}")
  endif()
  if(OCEAN_PROGRAMS_ONLY)
    # No ctest here: the smoke run is listed for the script that drives these programs (./ocean
    # windows --smoke runs each under wine): the step, its golden, its SMOKE_FLAGS.
    string(JOIN " " _smoke_line ${name} "${golden}" ${ARG_SMOKE_FLAGS})
    file(APPEND "${CMAKE_BINARY_DIR}/smoke_runs.txt" "${_smoke_line}\n")
    set_property(GLOBAL APPEND PROPERTY OCEAN_STEPS ${name})
    set(OCEAN_STEP ${name} PARENT_SCOPE)
    return()
  endif()

  # The chapter's test executables: NAME_tests (CPU) and NAME_gpu_tests (a headless GL context),
  # both in the core tier. Each build declares (and so builds) only the tests worth running in it
  # (the top CMakeLists.txt, "The tests a build declares"): the portable builds leave out the CPU
  # tests, whose results no GL profile changes, and the GPU tests, which read results back with
  # compute shaders and GL 4.5 calls; the sanitizer build leaves out the GPU tests, which check
  # llvmpipe's arithmetic more than our C++ at thirty times the cost.
  foreach(kind tests gpu_tests)
    if(kind STREQUAL "tests")
      set(files ${ARG_TESTS})
      set(labels "unit;core;${name}")
      if(OCEAN_GL_PORTABLE)
        set(files "")
      endif()
    else()
      set(files ${ARG_GPU_TESTS})
      set(labels "gpu;core;${name}")
      if(OCEAN_GL_PORTABLE OR OCEAN_SANITIZE)
        set(files "")
        set(ARG_TEST_SHADERS "")
      endif()
    endif()
    if(NOT files)
      continue()
    endif()
    set(exe ${name}_${kind})
    if(kind STREQUAL "tests")
      add_executable(${exe} ${files})
      target_link_libraries(${exe} PRIVATE ocean_common GTest::gtest_main ${ARG_LINKS})
    else()
      add_executable(${exe} "${OCEAN_TESTS_DIR}/gpu/gpu_main.cpp" ${files})
      target_link_libraries(${exe} PRIVATE ocean_common GTest::gtest ${ARG_LINKS})
    endif()
    if(ARG_LIBRARY)
      target_link_libraries(${exe} PRIVATE ${name}_lib)
    endif()
    target_include_directories(${exe} PRIVATE "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
    target_compile_definitions(${exe} PRIVATE OCEAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
      OCEAN_STEP_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
    ocean_warnings(${exe})
    # LeakSanitizer checks the CPU tests (cmake/GoogleTests.cmake).
    if(kind STREQUAL "tests")
      ocean_gtests(${exe} "${name}." LABELS ${labels} LEAK_CHECK)
    else()
      ocean_gtests(${exe} "${name}." LABELS ${labels})
    endif()
  endforeach()

  # The chapter's exercises (./ocean exercise): exercises/exercise compiles every chapter's list in.
  foreach(file IN LISTS ARG_EXERCISES)
    set_property(GLOBAL APPEND PROPERTY OCEAN_EXERCISES "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
  endforeach()
  # ... and links the chapter's library, whose CPU reference the checks call.
  if(ARG_EXERCISES AND ARG_LIBRARY)
    set_property(GLOBAL APPEND PROPERTY OCEAN_EXERCISE_LIBRARIES ${name}_lib)
  endif()

  set_property(GLOBAL APPEND PROPERTY OCEAN_STEPS ${name})
  set_property(GLOBAL APPEND PROPERTY OCEAN_SHADERS ${ARG_SHADERS})
  list(TRANSFORM ARG_TEST_SHADERS PREPEND "${CMAKE_CURRENT_SOURCE_DIR}/")
  set_property(GLOBAL APPEND PROPERTY OCEAN_SHADERS ${ARG_TEST_SHADERS})

  set(OCEAN_STEP ${name} PARENT_SCOPE)

  add_test(NAME ${name}.smoke
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/smoke.sh" $<TARGET_FILE:${name}>
            $<TARGET_FILE:image_compare> "${golden}" "${CMAKE_BINARY_DIR}/test-output/smoke/${name}" ${ARG_SMOKE_FLAGS})
  set_property(GLOBAL PROPERTY OCEAN_SMOKE_FLAGS_${name} ${ARG_SMOKE_FLAGS})  # the browser's smoke run takes them too
  set_tests_properties(${name}.smoke PROPERTIES LABELS "smoke;gpu;core;${name}" TIMEOUT 300)

  if(OCEAN_SANITIZE)
    return()  # a real window runs the same C++ as the headless smoke test
  endif()
  add_test(NAME ${name}.windowed
    COMMAND bash "${OCEAN_TESTS_DIR}/smoke/windowed.sh" $<TARGET_FILE:${name}>)
  # RESOURCE_LOCK: two `xvfb-run -a` starting at once can race for the same display number.
  # XDG_CONFIG_HOME: a folder of the build's, so that a learner's saved panel is never read.
  set_tests_properties(${name}.windowed PROPERTIES LABELS "windowed;gpu;${name}" TIMEOUT 300 RESOURCE_LOCK xvfb
    SKIP_RETURN_CODE 77 ENVIRONMENT "XDG_CONFIG_HOME=${CMAKE_BINARY_DIR}/test-output/config")
endfunction()

