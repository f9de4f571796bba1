#include "step05_fft/box_mipmaps.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <string>

namespace step05 {

void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture) {
    GLint target = 0, levels = 0, format = 0, size = 0, layers = 1;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &size);
    if (target == GL_TEXTURE_2D_ARRAY) glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
    if (target == GL_TEXTURE_CUBE_MAP) layers = 6;
    const char* image_format = format == GL_RGBA32F ? "rgba32f"
                               : format == GL_RGBA16F ? "rgba16f"
                               : format == GL_RG32F   ? "rg32f"
                               : format == GL_R32F    ? "r32f"
                                                      : nullptr;
    if (image_format == nullptr) throw ocean::Error("make_box_mipmaps: only RGBA32F, RGBA16F, RG32F and R32F");
    if (target != GL_TEXTURE_2D && target != GL_TEXTURE_2D_ARRAY && target != GL_TEXTURE_CUBE_MAP)
        throw ocean::Error("make_box_mipmaps: only 2D textures, 2D arrays and cube maps");
    const bool layered = target != GL_TEXTURE_2D;
    const char* image = target == GL_TEXTURE_CUBE_MAP ? "imageCube" : layered ? "image2DArray" : "image2D";
    const std::vector<std::string> defines{std::string("FORMAT ") + image_format,
                                           std::string("IMAGE ") + image,
                                           std::string("LAYERED ") + (layered ? "1" : "0")};
    ocean::ShaderProgram* p = programs("box_mip.comp", {"step05_fft/shaders/box_mip.comp"}, defines);
    if (p == nullptr) throw ocean::Error("box_mip.comp does not build");
    glUseProgram(p->id());
    // Four levels a dispatch: 256 x 256 takes two (levels 1-4, 5-8), 512 x 512 three.
    for (int level = 1; level < levels; level += 4) {
        const int count = std::min(4, levels - level), level_size = std::max(1, size >> level);
        p->set("u_size", level_size);
        p->set("u_count", count);
        glBindImageTexture(0, texture, level - 1, layered, 0, GL_READ_ONLY, GLenum(format));
        // Units past u_count are never written; they are bound to a level that exists all the same.
        for (int k = 0; k < 4; ++k)
            glBindImageTexture(GLuint(1 + k), texture, level + std::min(k, count - 1), layered, 0, GL_WRITE_ONLY,
                               GLenum(format));
        const GLuint groups = GLuint((level_size + 15) / 16);
        glDispatchCompute(groups, groups, GLuint(layers));
        // The next dispatch reads this one's last level through its image.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace step05
