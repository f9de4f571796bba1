#include "step06_foam_sky/box_mipmaps.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <string>

namespace step06 {

void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture, MipTarget target, GLenum format,
                      int size, int layers, int levels) {
    if (format != GL_RGBA16F && format != GL_R32F) throw ocean::Error("make_box_mipmaps: only RGBA16F and R32F");
    const char* image = target == MipTarget::Cube ? "imageCube" : target == MipTarget::Array ? "image2DArray" : "image2D";
    const std::vector<std::string> defines{std::string("FORMAT ") + (format == GL_RGBA16F ? "rgba16f" : "r32f"),
                                           std::string("IMAGE ") + image,
                                           std::string("LAYERED ") + (target == MipTarget::Plain ? "0" : "1")};
    ocean::ShaderProgram* p = programs("box_mip.comp", {"step06_foam_sky/shaders/box_mip.comp"}, defines);
    if (p == nullptr) throw ocean::Error("box_mip.comp does not build");
    glUseProgram(p->id());
    const GLboolean layered = target == MipTarget::Plain ? GL_FALSE : GL_TRUE;
    for (int level = 1; level < levels; ++level) {
        const int level_size = std::max(1, size >> level);
        p->set("u_size", level_size);
        glBindImageTexture(0, texture, level - 1, layered, 0, GL_READ_ONLY, format);
        glBindImageTexture(1, texture, level, layered, 0, GL_WRITE_ONLY, format);
        const GLuint groups = GLuint((level_size + 7) / 8);
        glDispatchCompute(groups, groups, GLuint(target == MipTarget::Plain ? 1 : layers));
        // The next level reads this one through its image.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace step06
