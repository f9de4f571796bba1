# driver_tests: the ./ocean driver given bad input, on what ctest built (OCEAN_NO_BUILD=1: they
# never build; OCEAN_BUILD_DIR: this build tree). The driver cds to its own folder, so both run
# ${PROJECT_SOURCE_DIR}/ocean.

# tools.driver_catalogue: a table of bad input for every subcommand (tests/cli/driver_catalogue.sh):
# steps given as patterns or paths, numbers that are not numbers or out of range, sizes, flags
# without their value, lab names and exercise numbers with shell or sed in them, extra arguments.
# Each is refused with exactly one "ocean: error:" line, and no canary file, no temporary file and
# no change to the repository is left behind; a few valid lines run (or dry-run) with exit 0, and
# Ctrl-C leaves no temporary file.
add_test(NAME tools.driver_catalogue
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/driver_catalogue.sh" "${PROJECT_SOURCE_DIR}/ocean"
          "${CMAKE_BINARY_DIR}" "${CMAKE_BINARY_DIR}/test-output/driver_catalogue")
# tools.driver_fuzz: 200 random command lines from a fixed seed (tests/cli/driver_fuzz.sh), under
# OCEAN_DRY_RUN=1: exit 0, 1 or 2, a failure's one line "ocean: error: ...", no bash message,
# no canary, no temporary file.
add_test(NAME tools.driver_fuzz
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/driver_fuzz.sh" "${PROJECT_SOURCE_DIR}/ocean"
          "${CMAKE_BINARY_DIR}" "${CMAKE_BINARY_DIR}/test-output/driver_fuzz" 200)
set_tests_properties(tools.driver_catalogue tools.driver_fuzz PROPERTIES COST 25
  LABELS "bad_input;tools" TIMEOUT 300
  ENVIRONMENT "OCEAN_NO_BUILD=1;OCEAN_BUILD_DIR=${CMAKE_BINARY_DIR}")

# tools.driver_platforms: ./ocean where there is no apt (tests/cli/driver_platforms.sh): macOS
# without Homebrew, and another system without cmake, each told in one line what to install.
add_test(NAME tools.driver_platforms
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/driver_platforms.sh" "${PROJECT_SOURCE_DIR}/ocean"
          "${CMAKE_BINARY_DIR}/test-output/driver_platforms")
set_tests_properties(tools.driver_platforms PROPERTIES LABELS "bad_input;tools" TIMEOUT 60)

# tools.source_archives: the sources some builds compile (tools/source_archives.sh) are refused,
# in one line, when a file differs from its recorded hash; apt's deb822 sources become deb-src lines.
add_test(NAME tools.source_archives
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/source_archives.sh" "${PROJECT_SOURCE_DIR}"
          "${CMAKE_BINARY_DIR}/test-output/source_archives")
set_tests_properties(tools.source_archives PROPERTIES LABELS "bad_input;tools" TIMEOUT 60)
