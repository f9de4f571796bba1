# Warnings on for our own code only (glad and the system libraries are not ours to fix).
# MSVC (the windows-msvc preset) takes its own spelling: level 4, standard conformance, UTF-8
# sources, and std::getenv and the like without the deprecation it warns of.
function(ocean_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive- /utf-8)
    target_compile_definitions(${target} PRIVATE _CRT_SECURE_NO_WARNINGS _USE_MATH_DEFINES)
    if(OCEAN_WERROR)
      target_compile_options(${target} PRIVATE /WX)
    endif()
    return()
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(OCEAN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
