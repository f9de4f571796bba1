// make_box_mipmaps (box_mipmaps.hpp, shaders/box_mip.comp) on the GPU, against the 2 x 2 mean it
// claims and against glGenerateMipmap, whose place it takes: the simulation's maps here, step06's
// sky, combined levels and foam there.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "step05_fft/box_mipmaps.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

namespace {

using namespace step05;

struct BoxMipmaps : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    ocean::ProgramFactory factory() { return cache.factory(); }
};

// make_box_mipmaps: every level of a cube (RGBA16F, the sky's), 2D arrays (RGBA32F, step05's
// simulated maps; RGBA16F, the combined levels; RG32F, the foam's; R32F) and a plain 2D texture
// (R32F) is the 2 x 2 mean of the level above it, as the
// GPU read it back (so each level is held to its own input, within one rounding to the format),
// and the same as glGenerateMipmap makes of the same level 0.
TEST_F(BoxMipmaps, AreTheMeanOfTheLevelAboveAsGlGenerateMipmapMakes) {
    struct Case {
        const char* name;
        GLenum gl_target;
        GLenum format;
        int layers, channels;
        double relative;  // one rounding to the format, with a margin of 2
    };
    // Half floats keep 10 bits of mantissa: one step is up to 2^-10 of the value (llvmpipe
    // truncates, and reaches 9.5e-4 here), floats 2^-23.
    const Case cases[] = {{"cube RGBA16F", GL_TEXTURE_CUBE_MAP, GL_RGBA16F, 6, 4, 2.0 / 1024},
                          {"2D array RGBA32F", GL_TEXTURE_2D_ARRAY, GL_RGBA32F, 4, 4, 1e-6},
                          {"2D array RGBA16F", GL_TEXTURE_2D_ARRAY, GL_RGBA16F, 3, 4, 2.0 / 1024},
                          {"2D array RG32F", GL_TEXTURE_2D_ARRAY, GL_RG32F, 3, 2, 1e-6},
                          {"2D array R32F", GL_TEXTURE_2D_ARRAY, GL_R32F, 3, 1, 1e-6},
                          {"2D R32F", GL_TEXTURE_2D, GL_R32F, 1, 1, 1e-6}};
    const int size = 16, levels = 5;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    for (const Case& c : cases) {
        const GLenum pixel_format = c.channels == 4 ? GL_RGBA : c.channels == 2 ? GL_RG : GL_RED;
        std::vector<float> level0(std::size_t(size * size * c.layers * c.channels));
        for (float& v : level0) v = value(random);
        const auto upload = [&](const ocean::Texture& t) {
            if (c.gl_target == GL_TEXTURE_2D) {
                glTextureStorage2D(t.id(), levels, c.format, size, size);
                glTextureSubImage2D(t.id(), 0, 0, 0, size, size, pixel_format, GL_FLOAT, level0.data());
            } else {
                if (c.gl_target == GL_TEXTURE_CUBE_MAP)
                    glTextureStorage2D(t.id(), levels, c.format, size, size);
                else
                    glTextureStorage3D(t.id(), levels, c.format, size, size, c.layers);
                glTextureSubImage3D(t.id(), 0, 0, 0, 0, size, size, c.layers, pixel_format, GL_FLOAT,
                                    level0.data());
            }
        };
        const auto read = [&](const ocean::Texture& t, int level) {
            const int n = size >> level;
            std::vector<float> texels(std::size_t(n * n * c.layers * c.channels));
            glGetTextureImage(t.id(), level, pixel_format, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                              texels.data());
            return texels;
        };
        ocean::Texture ours = ocean::make_texture(c.gl_target), gl = ocean::make_texture(c.gl_target);
        upload(ours);
        upload(gl);
        make_box_mipmaps(factory(), ours.id());
        glGenerateTextureMipmap(gl.id());
        double worst_box = 0, worst_gl = 0;
        for (int level = 1; level < levels; ++level) {
            const std::vector<float> above = read(ours, level - 1), below = read(ours, level),
                                     theirs = read(gl, level);
            const int n = size >> level;
            for (int layer = 0; layer < c.layers; ++layer)
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        for (int k = 0; k < c.channels; ++k) {
                            const auto at = [&](const std::vector<float>& v, int side, int x, int y) {
                                return double(
                                    v[((std::size_t(layer) * side + y) * side + x) * c.channels + k]);
                            };
                            const double mean =
                                0.25 *
                                (at(above, 2 * n, 2 * i, 2 * j) + at(above, 2 * n, 2 * i + 1, 2 * j) +
                                 at(above, 2 * n, 2 * i, 2 * j + 1) + at(above, 2 * n, 2 * i + 1, 2 * j + 1));
                            worst_box = std::max(worst_box, std::abs(at(below, n, i, j) - mean) / mean);
                            worst_gl = std::max(worst_gl, std::abs(at(below, n, i, j) - at(theirs, n, i, j)) /
                                                              at(theirs, n, i, j));
                        }
        }
        std::printf("%s: worst relative gap to the 2 x 2 mean %.2e, to glGenerateMipmap %.2e (levels 1-%d)\n",
                    c.name, worst_box, worst_gl, levels - 1);
        EXPECT_LT(worst_box, c.relative);
        // glGenerateMipmap's own rounding compounds over the levels: four roundings.
        EXPECT_LT(worst_gl, 4 * c.relative);
    }
}

}  // namespace
