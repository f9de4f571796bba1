// Mipmaps made by a compute shader (shaders/box_mip.comp): each texel of level l the mean of the
// 2 x 2 texels it covers in level l - 1, which is what glGenerateMipmap makes of a power-of-two
// texture. On llvmpipe glGenerateMipmap is a blit per level and per layer, and it took 3 of the
// sky pass's 3.5 ms (the cube's 6 faces x 7 levels) and about 2 ms of the foam pass; a dispatch
// per level does all the layers at once (docs/performance.md).
#pragma once

#include "common/shader.hpp"

namespace step06 {

// What the texture is: a cube map, a 2D array or a plain 2D texture.
enum class MipTarget { Cube, Array, Plain };

// Levels 1 to levels - 1 of `texture` (square, `size` texels a side at level 0, `layers` layers:
// 6 for a cube), from level 0 down. `format` is GL_RGBA16F or GL_R32F, the formats step06 filters.
// Ends with the barrier that lets texture fetches read the new levels.
void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture, MipTarget target, GLenum format,
                      int size, int layers, int levels);

}  // namespace step06
