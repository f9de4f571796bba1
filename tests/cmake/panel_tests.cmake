# The panel as a learner uses it (issue: the window as a learner uses it). The unit tests
# (tests/unit/test_panel_*.cpp, in unit_tests: unit.PanelGroups.*, unit.PanelWindow.*,
# unit.PanelStateFile.*, unit.PanelStatePath.*) check the groups, the panel's rectangle from
# 640x360 up (a quarter at most, a readable number of rows, whole rows, following the window as it
# shrinks and grows), and its state carried between runs; here, what a run draws and prints.

# step05's split view at the default resolution 256, where its left half is the GPU FFT too, says
# so; at 64 it is the naive DFT (tests/smoke/panel_split_labels.sh).
if(TARGET step05_fft)
  add_test(NAME step05_fft.split_labels
    COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/smoke/panel_split_labels.sh" $<TARGET_FILE:step05_fft>)
  set_tests_properties(step05_fft.split_labels PROPERTIES LABELS "gpu;split;step05_fft" TIMEOUT 300)
endif()

# The panel a headless run draws (--ui), measured on its screenshot against the same frame without
# it: at 960x540 and 640x360 it covers at most a quarter of the window and lies inside it
# (gpu.PanelScreen.*; its own executable, as app_tests: App makes its own context).
add_executable(panel_screen_tests unit/test_panel_screen.cpp)
target_link_libraries(panel_screen_tests PRIVATE ocean_common GTest::gtest_main)
target_compile_definitions(panel_screen_tests PRIVATE OCEAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
ocean_warnings(panel_screen_tests)
ocean_gtests(panel_screen_tests "gpu." LABELS gpu)

# Every chapter's panel at its first size in 640x360 and 960x540: at most a quarter of the picture,
# inside it, and nothing in it cut off at its edge (tests/smoke/panel_fits.sh; the status lines
# wrap, a long parameter name goes above its widget, the next chapter's button below the previous
# one's where they do not fit side by side).
foreach(_step IN LISTS OCEAN_STEPS)
  add_test(NAME ${_step}.panel_fits
    COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/smoke/panel_fits.sh" $<TARGET_FILE:${_step}> $<TARGET_FILE:image_compare>)
  set_tests_properties(${_step}.panel_fits PROPERTIES LABELS "gpu;${_step}" TIMEOUT 300)
endforeach()
