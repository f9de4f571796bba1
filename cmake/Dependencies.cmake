# Every dependency is a Debian package; ./ocean installs the missing ones (see its PACKAGES list).
find_package(glfw3 3.3 REQUIRED)          # libglfw3-dev: windows, input
find_package(glm REQUIRED)                # libglm-dev: vectors and matrices
find_package(PkgConfig REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)  # libimgui-dev 1.86, backends included
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)      # libstb-dev: stb_image, stb_image_write
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)      # libegl-dev: headless contexts
find_package(GTest REQUIRED)              # libgtest-dev

find_program(GLAD_EXECUTABLE glad REQUIRED)              # python3-glad
find_program(GLSLANG_VALIDATOR glslangValidator)         # glslang-tools (a test, optional to build)
find_program(XVFB_RUN xvfb-run)                          # xvfb (windowed tests, optional)

# imgui.a holds the GLFW and OpenGL3 backends, which call into GLFW.
add_library(ocean_imgui INTERFACE)
target_link_libraries(ocean_imgui INTERFACE PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})
pkg_check_modules(FFTW REQUIRED IMPORTED_TARGET fftw3)    # libfftw3-dev: the CPU FFT (step05), double
pkg_check_modules(FFTWF REQUIRED IMPORTED_TARGET fftw3f)  # the same package: single precision, and
find_library(FFTWF_THREADS fftw3f_threads REQUIRED)      # its threads (the FFTW backend, the floor)
find_package(Threads REQUIRED)
# libwebp-dev: tools/animate encodes the READMEs' animations (animated WebP, WebPAnimEncoder) and
# reads them back (WebPAnimDecoder) to check them.
pkg_check_modules(WEBP REQUIRED IMPORTED_TARGET libwebpmux libwebpdemux libwebp)
