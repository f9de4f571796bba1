# window_input: a step's real window driven by xdotool on Xvfb (tests/smoke/window_input.sh): key
# taps shorter than a frame act (F1 toggles the panel on every tap, Esc quits), a drag turns the
# camera from where the button went down, step01's mouse pans and zooms its plot, step07's arrows
# leave F1 working and a right click pushes the raft, step08's left click drops a stone on the sea
# and says why it drops none on the sky or beyond the wave field, step01's Next button hands over
# to step02 with both steps' lines in a log file, step04's --split names both variants, a drag
# within one frame prints its line of flags (step01's plot:, step04's camera:), Next from a paused
# step01 starts step02 paused. Skipped (77) without
# xvfb-run or xdotool.
set(_window_input "${CMAKE_CURRENT_SOURCE_DIR}/smoke/window_input.sh")
# Every chapter's keys (step07's through steer_push, which taps them too), then what users do most.
set(_cases)
foreach(_step IN LISTS OCEAN_STEPS)
  if(NOT _step STREQUAL "step07_buoyancy")
    list(APPEND _cases "${_step}\;keys")
  endif()
endforeach()
foreach(_case IN LISTS _cases ITEMS "step07_buoyancy;steer_push" "step04_fbm;drag" "step01_sine2d;plot"
                                    "step01_sine2d;next" "step04_fbm;split"
                                    "step01_sine2d;quick_drag" "step04_fbm;quick_drag" "step01_sine2d;next_paused"
                                    "step08_wakes;stone")
  list(GET _case 0 _step)
  list(GET _case 1 _kind)
  set(_flags)
  if(_kind STREQUAL "drag")
    set(_flags --set camera_yaw=0 --set camera_pitch=20)
  elseif(_kind STREQUAL "split")
    set(_flags --split)
  elseif(_kind STREQUAL "next_paused")
    set(_flags --paused)
  endif()
  set(_name ${_step}.window_input.${_kind})
  add_test(NAME ${_name} COMMAND bash "${_window_input}" ${_kind} $<TARGET_FILE:${_step}> ${_flags})
  # ARROWS_HELD_S: seconds the arrows are held (read as held once a frame); FRAME_WAIT_S: seconds
  # for what was sent within one frame to show (window_input.sh).
  set_tests_properties(${_name} PROPERTIES LABELS "windowed;gpu;${_step}" TIMEOUT 120 SKIP_RETURN_CODE 77
                                           RUN_SERIAL TRUE
                                           ENVIRONMENT "XDG_CONFIG_HOME=${CMAKE_BINARY_DIR}/test-output/config;ARROWS_HELD_S=1;FRAME_WAIT_S=10")
endforeach()
