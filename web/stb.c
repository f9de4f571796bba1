/* stb_image and stb_image_write compiled in: Debian's libstb provides them natively, the web
   build (cmake/Web.cmake) compiles the same headers here. */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
