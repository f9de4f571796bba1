/* The stb implementations the programs and tools use, compiled once where no libstb provides them
   (Debian's libstb does natively): the browser (cmake/Web.cmake), the Windows cross-build and
   macOS (cmake/SourceTrees.cmake). */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#include <stb_truetype.h>
