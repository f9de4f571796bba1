# web: each chapter, as a page in headless chromium (tests/web):
# its smoke run matches the native golden within the browser's tolerance with nothing in the
# console but logs, and a parameter set from the address changes step02's picture. They drive the
# pages ./ocean web built into OCEAN_WEB_SITE, and are skipped (77) where there are none.
set(OCEAN_WEB_SITE "${PROJECT_SOURCE_DIR}/build/web/site" CACHE PATH "the pages ./ocean web builds (tests/web)")
set(_web_smoke "${CMAKE_CURRENT_SOURCE_DIR}/web/smoke.sh")
foreach(_step IN LISTS OCEAN_STEPS)
  get_property(_smoke_flags GLOBAL PROPERTY OCEAN_SMOKE_FLAGS_${_step})  # what the golden holds still
  add_test(NAME ${_step}.web.smoke
    COMMAND bash "${_web_smoke}" "${OCEAN_WEB_SITE}" ${_step} $<TARGET_FILE:image_compare>
            "${PROJECT_SOURCE_DIR}/${_step}/golden.png" "${CMAKE_BINARY_DIR}/test-output/web/${_step}" ${_smoke_flags})
  set_tests_properties(${_step}.web.smoke PROPERTIES LABELS "web;${_step}" TIMEOUT 240 SKIP_RETURN_CODE 77)
endforeach()
# step07's bodies read the sea a frame late without compute shaders, the golden's on FFTW's maps of
# each frame: natively its limit is 5 (step07_buoyancy/CMakeLists.txt), here the browser's 1.5 more.
# Measured 4.10, as natively in ES 3.0 (4.00).
if(TEST step07_buoyancy.web.smoke)
  set_tests_properties(step07_buoyancy.web.smoke PROPERTIES ENVIRONMENT "SMOKE_RMSE=6.5")
endif()
# step08 composes step07's bodies and feed, so the same: its boat, and the wake it presses, a frame
# behind the golden's. Measured 4.52 (0.91 % of pixels off by more than 24, within the 1 %), the same with
# the frame loop through Asyncify as through emscripten_set_main_loop.
if(TEST step08_wakes.web.smoke)
  set_tests_properties(step08_wakes.web.smoke PROPERTIES ENVIRONMENT "SMOKE_RMSE=6.5")
endif()
# step09 is step08's scene with its bodies' waves: the same, not yet measured in a browser.
if(TEST step09_radiation.web.smoke)
  set_tests_properties(step09_radiation.web.smoke PROPERTIES ENVIRONMENT "SMOKE_RMSE=6.5")
endif()
# step10 seen from below: the ES profile's patches, cut on the CPU, flip isolated pixels of the
# surface across the critical angle (step10_underwater/CMakeLists.txt). Measured 6.64, 0.97 %.
if(TEST step10_underwater.web.smoke)
  set_tests_properties(step10_underwater.web.smoke PROPERTIES ENVIRONMENT "SMOKE_RMSE=8;SMOKE_BAD_FRACTION=0.02")
endif()
add_test(NAME step02_sine3d.web.address_sets_a_parameter
  COMMAND bash "${_web_smoke}" "${OCEAN_WEB_SITE}" step02_sine3d $<TARGET_FILE:image_compare>
          "${PROJECT_SOURCE_DIR}/step02_sine3d/golden.png" "${CMAKE_BINARY_DIR}/test-output/web/step02_sine3d"
          --query=amplitude=2.5)
set_tests_properties(step02_sine3d.web.address_sets_a_parameter PROPERTIES LABELS "web;step02_sine3d" TIMEOUT 240
                     SKIP_RETURN_CODE 77)
# The lessons as the index leads to them: each chapter's README, and every page of the site a link
# leads to from there, an HTML page (web/render_lessons.mjs) whose pictures load and whose links
# answer, served by web/serve.py as ./ocean web serves them (tests/web/lessons.js).
add_test(NAME web.lessons_from_the_index
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/web/lessons.sh" "${PROJECT_SOURCE_DIR}" "${OCEAN_WEB_SITE}")
set_tests_properties(web.lessons_from_the_index PROPERTIES LABELS "web" TIMEOUT 120 SKIP_RETURN_CODE 77)
# The read-back of the sea (step07's map_readback.hpp), in step07 and in step08 which composes it
# (step09 is step08's scene: the same read-back), 60 frames: chromium's warning about a read-back
# buffer at most once, not once a frame (tests/web/readback_quiet.sh; about 15 s each).
foreach(_step IN ITEMS step07_buoyancy step08_wakes)
  if(_step IN_LIST OCEAN_STEPS)
    add_test(NAME ${_step}.web.readback_quiet
      COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/web/readback_quiet.sh" "${OCEAN_WEB_SITE}" ${_step}
              "${CMAKE_BINARY_DIR}/test-output/web/${_step}")
    set_tests_properties(${_step}.web.readback_quiet PROPERTIES LABELS "web;${_step}" TIMEOUT 240 SKIP_RETURN_CODE 77)
  endif()
endforeach()
