// make_box_mipmaps (box_mipmaps.hpp, shaders/box_mip.comp) on the GPU, against the 2 x 2 mean it
// claims and against glGenerateMipmap, whose place it takes: the simulation's maps, and the other
// kinds and formats it takes (a cube map, 2D maps of GL_RGBA16F, GL_RG32F, GL_R32F).
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "common/error.hpp"
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
// (R32F) is the mean of the block of level 0 it covers, 2^l x 2^l texels at level l, and the same
// as glGenerateMipmap makes of the same level 0. 64 x 64 texels, so that level 1 spans two
// workgroups a side and the seven levels take two dispatches (1-4 from level 0, 5-6 from level 4
// as stored); a chain stopped at level 5 (the texture's storage has 6 levels), so that the second
// dispatch makes one level and must not write past the texture's last; and two textures made
// together (the simulation's maps, the combined levels): three levels a dispatch, each texture
// its own.
TEST_F(BoxMipmaps, AreTheMeanOfTheLevelAboveAsGlGenerateMipmapMakes) {
    struct Case {
        const char* name;
        GLenum gl_target;
        GLenum format;
        int layers, channels, levels;
        double step;  // one rounding to the format, relative
        int maps = 1;  // textures made together
    };
    // Half floats keep 10 bits of mantissa: one rounding is up to 2^-10 of the value (llvmpipe
    // truncates, and reaches 9.5e-4), floats 2^-23 (with a margin for the sums' own roundings).
    const double half = 1.0 / 1024, single = 1e-6 / 2;
    const Case cases[] = {{"cube RGBA16F", GL_TEXTURE_CUBE_MAP, GL_RGBA16F, 6, 4, 7, half},
                          {"2D array RGBA32F", GL_TEXTURE_2D_ARRAY, GL_RGBA32F, 4, 4, 7, single},
                          {"2D array RGBA16F", GL_TEXTURE_2D_ARRAY, GL_RGBA16F, 3, 4, 7, half},
                          {"2D array RG32F", GL_TEXTURE_2D_ARRAY, GL_RG32F, 3, 2, 7, single},
                          {"2D array R32F", GL_TEXTURE_2D_ARRAY, GL_R32F, 3, 1, 7, single},
                          {"2D R32F", GL_TEXTURE_2D, GL_R32F, 1, 1, 7, single},
                          {"2D array RGBA32F, 6 of 7 levels", GL_TEXTURE_2D_ARRAY, GL_RGBA32F, 2, 4, 6, single},
                          {"two 2D arrays RGBA32F together", GL_TEXTURE_2D_ARRAY, GL_RGBA32F, 4, 4, 7, single, 2},
                          {"two 2D arrays RGBA16F together", GL_TEXTURE_2D_ARRAY, GL_RGBA16F, 3, 4, 7, half, 2}};
    const int size = 64;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    for (const Case& c : cases) {
        const int levels = c.levels, per_dispatch = c.maps == 1 ? 4 : 3;
        const GLenum pixel_format = c.channels == 4 ? GL_RGBA : c.channels == 2 ? GL_RG : GL_RED;
        const auto upload = [&](const ocean::Texture& t, const std::vector<float>& level0) {
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
        std::vector<ocean::Texture> ours, gl;
        for (int m = 0; m < c.maps; ++m) {
            std::vector<float> level0(std::size_t(size * size * c.layers * c.channels));
            for (float& v : level0) v = value(random);
            ours.push_back(ocean::make_texture(c.gl_target));
            gl.push_back(ocean::make_texture(c.gl_target));
            upload(ours.back(), level0);
            upload(gl.back(), level0);
            glGenerateTextureMipmap(gl.back().id());
        }
        if (c.maps == 1)
            make_box_mipmaps(factory(), ours[0].id());
        else
            make_box_mipmaps(factory(), ours[0].id(), ours[1].id());
        for (int m = 0; m < c.maps; ++m) {
            const std::vector<float> stored0 = read(ours[std::size_t(m)], 0);  // level 0 as the format holds it
            for (int level = 1; level < levels; ++level) {
                const std::vector<float> below = read(ours[std::size_t(m)], level),
                                         theirs = read(gl[std::size_t(m)], level);
                const int n = size >> level, block = 1 << level;
                // The first dispatch's levels are one rounding from the exact mean, the second's two
                // (it starts from the first's last level as stored): a margin of 2 on that.
                // glGenerateMipmap rounds at every level, so it may be `level` roundings away.
                const double ours_limit = 2 * c.step * (1 + (level - 1) / per_dispatch),
                             gl_limit = ours_limit + 2 * c.step * level;
                double worst_box = 0, worst_gl = 0;
                for (int layer = 0; layer < c.layers; ++layer)
                    for (int j = 0; j < n; ++j)
                        for (int i = 0; i < n; ++i)
                            for (int k = 0; k < c.channels; ++k) {
                                const auto at = [&](const std::vector<float>& v, int side, int x, int y) {
                                    return double(
                                        v[((std::size_t(layer) * side + y) * side + x) * c.channels + k]);
                                };
                                double mean = 0;
                                for (int y = 0; y < block; ++y)
                                    for (int x = 0; x < block; ++x)
                                        mean += at(stored0, size, i * block + x, j * block + y);
                                mean /= double(block * block);
                                worst_box = std::max(worst_box, std::abs(at(below, n, i, j) - mean) / mean);
                                worst_gl = std::max(worst_gl, std::abs(at(below, n, i, j) - at(theirs, n, i, j)) /
                                                                  at(theirs, n, i, j));
                            }
                std::printf("%s, texture %d, level %d: worst relative gap to the block mean %.2e (limit %.1e), to "
                            "glGenerateMipmap %.2e (limit %.1e)\n",
                            c.name, m, level, worst_box, ours_limit, worst_gl, gl_limit);
                EXPECT_LT(worst_box, ours_limit) << c.name << ", texture " << m << ", level " << level;
                EXPECT_LT(worst_gl, gl_limit) << c.name << ", texture " << m << ", level " << level;
            }
        }
    }
}

// Textures made together must be alike: one line of error, not a wrong mipmap.
TEST_F(BoxMipmaps, TexturesMadeTogetherMustBeAlike) {
    ocean::Texture a = ocean::make_texture(GL_TEXTURE_2D_ARRAY), b = ocean::make_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(a.id(), 5, GL_RGBA32F, 16, 16, 2);
    glTextureStorage3D(b.id(), 4, GL_RGBA32F, 8, 8, 2);
    EXPECT_THROW(make_box_mipmaps(factory(), a.id(), b.id()), ocean::Error);
}

}  // namespace
