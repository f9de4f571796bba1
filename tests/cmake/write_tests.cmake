# write_tests: see the comments of each test below.

# Every kind of file the programs write (a step's screenshot, --record frames, --save-preset,
# step05/06/07's --export with step07's trajectories, the tools' animate, image_panel,
# contact_sheet and bench_chart outputs, and a chapter's figure program's, step02_sine3d_figures),
# written onto a full disk (ulimit -f with SIGXFSZ ignored): one error line naming the file, a
# non-zero exit, no success line and no half-written or temporary file left
# (tests/cli/full_disk.sh). Each writer also runs once without
# the limit, which must succeed. Small pictures, two frames (step07: 100 tiny ones).
add_test(NAME tools.full_disk
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/cli/full_disk.sh" "${CMAKE_BINARY_DIR}" "${PROJECT_SOURCE_DIR}"
          "${CMAKE_BINARY_DIR}/test-output/full_disk")
set_tests_properties(tools.full_disk PROPERTIES LABELS "bad_input;tools;gpu" TIMEOUT 240)
