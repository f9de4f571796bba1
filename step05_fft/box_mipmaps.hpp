// Mipmaps made by a compute shader (shaders/box_mip.comp): each texel of level l the mean of the
// 2 x 2 texels it covers in level l - 1, which is what glGenerateMipmap makes of a power-of-two
// texture. Drivers make glGenerateMipmap a draw or a blit per level and per layer: on llvmpipe it
// took 3 of the 3.5 ms a sky cube map's pass took (6 faces x 7 levels), and on an NVIDIA H100 or
// H200 0.67 of the 0.73 ms the GPU simulation took (its two maps' 4 layers x 8 levels). One
// dispatch makes up to four levels of every layer (a workgroup carries its tile down in shared
// memory), since on a GPU a dispatch and its barrier cost more than the averaging: two dispatches
// for 256 x 256, where a dispatch a level took eight (docs/performance.md).
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

#include <cmath>

namespace step05 {

// In place of glGenerateTextureMipmap(texture): levels 1 and below of a square, immutable
// power-of-two texture, from level 0 down. The texture says what it is (a cube map, a 2D array or
// a 2D texture; its size, layers and levels); its format must be GL_RGBA32F (the simulation's
// maps), GL_RGBA16F, GL_RG32F or GL_R32F (a sky's cube map, other maps). Ends with the
// barrier that lets texture fetches read the new levels.
void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture);
// Two textures of the same kind, size and format, in the same dispatches (three levels a dispatch
// where one texture alone gets four): the simulation's two maps, the combined levels' two. On an
// H100 each dispatch saved is 5 to 7 microseconds.
void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint first, GLuint second);

// Levels 1 and below of `texture` (its `target`: GL_TEXTURE_2D_ARRAY or GL_TEXTURE_CUBE_MAP), in
// the profile's way: make_box_mipmaps where there are compute shaders, glGenerateMipmap where not
// (GL 4.1, ES 3.0), whose box filter the specification recommends.
inline void make_mipmaps(const ocean::ProgramFactory& programs, const ocean::Texture& texture, GLenum target) {
#ifdef OCEAN_GL_PORTABLE
    (void)programs;
    ocean::generate_mipmaps(texture, target);
#else
    (void)target;
    make_box_mipmaps(programs, texture.id());
#endif
}

// The levels of a full mip chain of a size x size texture, down to 1 x 1: what its storage needs
// for make_box_mipmaps (or glGenerateTextureMipmap) to fill.
inline int mip_levels(int size) { return 1 + int(std::floor(std::log2(double(size)))); }

}  // namespace step05
