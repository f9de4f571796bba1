# glad generates the GL 4.5 core (4.1 core in the portable build, ES 3.0 in the ES build) and,
# where headless runs go through EGL (OCEAN_EGL), the EGL 1.5 loader, at configure time, into the
# build tree.
# --reproducible makes it use the spec shipped with the package (no download: we are offline).
set(OCEAN_GLAD_DIR "${CMAKE_BINARY_DIR}/glad")
set(OCEAN_GLAD_EXTENSIONS GL_KHR_debug)
if(OCEAN_EGL)
  list(APPEND OCEAN_GLAD_EXTENSIONS
    EGL_EXT_platform_base EGL_EXT_platform_device EGL_EXT_device_base EGL_EXT_device_enumeration
    EGL_EXT_device_query EGL_MESA_platform_surfaceless EGL_KHR_create_context
    EGL_KHR_surfaceless_context EGL_KHR_no_config_context)
endif()
string(REPLACE ";" "," _glad_ext "${OCEAN_GLAD_EXTENSIONS}")
# The portable build's loader stops at GL 4.1 core, the ES build's at OpenGL ES 3.0: a call from a
# later version does not compile there.
if(OCEAN_GL_ES)
  set(_glad_gl gles2=3.0)
  set(_glad_gl_source gles2.c)
elseif(OCEAN_GL_PORTABLE)
  set(_glad_gl gl:core=4.1)
  set(_glad_gl_source gl.c)
else()
  set(_glad_gl gl:core=4.5)
  set(_glad_gl_source gl.c)
endif()
set(_glad_api ${_glad_gl})
set(_glad_sources "${OCEAN_GLAD_DIR}/src/${_glad_gl_source}")
if(OCEAN_EGL)
  string(APPEND _glad_api ",egl=1.5")
  list(APPEND _glad_sources "${OCEAN_GLAD_DIR}/src/egl.c")
endif()
set(_glad_args --quiet --reproducible --api ${_glad_api} --extensions ${_glad_ext}
    --out-path "${OCEAN_GLAD_DIR}" c --loader)
set(_glad_stamp "${OCEAN_GLAD_DIR}/args.txt")

if(EXISTS "${_glad_stamp}")
  file(READ "${_glad_stamp}" _glad_previous)
endif()
if(NOT "${_glad_previous}" STREQUAL "${_glad_args}" OR NOT EXISTS "${OCEAN_GLAD_DIR}/src/${_glad_gl_source}")
  message(STATUS "Generating the loader with glad (${_glad_api})")
  file(REMOVE_RECURSE "${OCEAN_GLAD_DIR}")  # no file of another configuration's loader (egl.h) stays
  execute_process(COMMAND "${GLAD_EXECUTABLE}" ${_glad_args}
                  RESULT_VARIABLE _glad_result ERROR_VARIABLE _glad_error)
  if(NOT _glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed (${_glad_result}):\n${_glad_error}")
  endif()
  file(WRITE "${_glad_stamp}" "${_glad_args}")
endif()

add_library(glad STATIC ${_glad_sources})
target_include_directories(glad SYSTEM PUBLIC "${OCEAN_GLAD_DIR}/include")
target_link_libraries(glad PUBLIC ${CMAKE_DL_LIBS})
if(OCEAN_GL_PORTABLE)
  target_compile_definitions(glad PUBLIC OCEAN_GL_PORTABLE)  # everything that includes GL sees it
endif()
if(OCEAN_GL_ES)
  target_compile_definitions(glad PUBLIC OCEAN_GL_ES)
endif()
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
