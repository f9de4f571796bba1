# Warnings on for our own code only (glad and the system libraries are not ours to fix).
function(ocean_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(OCEAN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
