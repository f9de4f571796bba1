// Mipmaps made by a compute shader (shaders/box_mip.comp): each texel of level l the mean of the
// 2 x 2 texels it covers in level l - 1, which is what glGenerateMipmap makes of a power-of-two
// texture. On llvmpipe glGenerateMipmap is a blit per level and per layer, and it took 3 of the
// sky pass's 3.5 ms (the cube's 6 faces x 7 levels) and about 2 ms of the foam pass; a dispatch
// per level does all the layers at once (docs/performance.md).
#pragma once

#include "common/shader.hpp"

#include <cmath>

namespace step06 {

// In place of glGenerateTextureMipmap(texture): levels 1 and below of a square, immutable
// power-of-two texture, from level 0 down. The texture says what it is (a cube map, a 2D array or
// a 2D texture; its size, layers and levels); its format must be GL_RGBA16F or GL_R32F, the
// formats step06 filters. Ends with the barrier that lets texture fetches read the new levels.
void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture);

// The levels of a full mip chain of a size x size texture, down to 1 x 1: what its storage needs
// for make_box_mipmaps (or glGenerateTextureMipmap) to fill.
inline int mip_levels(int size) { return 1 + int(std::floor(std::log2(double(size)))); }

}  // namespace step06
