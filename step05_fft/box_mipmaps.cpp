#include "step05_fft/box_mipmaps.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <string>

namespace step05 {

namespace {

// What make_box_mipmaps needs to know of a texture, read from the texture itself.
struct MipmapTarget {
    GLint target = 0, levels = 0, format = 0, size = 0, layers = 1;
    bool operator==(const MipmapTarget& o) const {
        return target == o.target && levels == o.levels && format == o.format && size == o.size && layers == o.layers;
    }
};

MipmapTarget describe(GLuint texture) {
    MipmapTarget t;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &t.target);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &t.levels);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &t.format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &t.size);
    if (t.target == GL_TEXTURE_2D_ARRAY) glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &t.layers);
    if (t.target == GL_TEXTURE_CUBE_MAP) t.layers = 6;
    return t;
}

void make_mipmaps_together(const ocean::ProgramFactory& programs, const std::vector<GLuint>& textures) {
    const MipmapTarget t = describe(textures.front());
    for (GLuint other : textures)
        if (!(describe(other) == t))
            throw ocean::Error("make_box_mipmaps: textures made together must have the same kind, size and format");
    const char* image_format = t.format == GL_RGBA32F ? "rgba32f"
                               : t.format == GL_RGBA16F ? "rgba16f"
                               : t.format == GL_RG32F   ? "rg32f"
                               : t.format == GL_R32F    ? "r32f"
                                                        : nullptr;
    if (image_format == nullptr) throw ocean::Error("make_box_mipmaps: only RGBA32F, RGBA16F, RG32F and R32F");
    if (t.target != GL_TEXTURE_2D && t.target != GL_TEXTURE_2D_ARRAY && t.target != GL_TEXTURE_CUBE_MAP)
        throw ocean::Error("make_box_mipmaps: only 2D textures, 2D arrays and cube maps");
    const bool layered = t.target != GL_TEXTURE_2D;
    const char* image = t.target == GL_TEXTURE_CUBE_MAP ? "imageCube" : layered ? "image2DArray" : "image2D";
    // GL promises a compute shader 8 image units: each texture's level above, and `per_dispatch`
    // levels below it of each.
    const int maps = int(textures.size()), per_dispatch = maps == 1 ? 4 : 3;
    const std::vector<std::string> defines{std::string("FORMAT ") + image_format,
                                           std::string("IMAGE ") + image,
                                           std::string("LAYERED ") + (layered ? "1" : "0"),
                                           "MAPS " + std::to_string(maps),
                                           "LEVELS " + std::to_string(per_dispatch)};
    ocean::ShaderProgram* p = programs("box_mip.comp", {"step05_fft/shaders/box_mip.comp"}, defines);
    if (p == nullptr) throw ocean::Error("box_mip.comp does not build");
    glUseProgram(p->id());
    // One texture of 256 x 256: two dispatches (levels 1-4, 5-8); two together: three (1-3, 4-6, 7-8).
    for (int level = 1; level < t.levels; level += per_dispatch) {
        const int count = std::min(per_dispatch, t.levels - level), level_size = std::max(1, t.size >> level);
        p->set("u_size", level_size);
        p->set("u_count", count);
        for (int m = 0; m < maps; ++m) {
            glBindImageTexture(GLuint(m), textures[std::size_t(m)], level - 1, layered, 0, GL_READ_ONLY, GLenum(t.format));
            // Units past u_count are never written; they are bound to a level that exists all the same.
            for (int k = 0; k < per_dispatch; ++k)
                glBindImageTexture(GLuint(maps + k * maps + m), textures[std::size_t(m)], level + std::min(k, count - 1),
                                   layered, 0, GL_WRITE_ONLY, GLenum(t.format));
        }
        const GLuint groups = GLuint((level_size + 15) / 16);
        glDispatchCompute(groups, groups, GLuint(t.layers));
        // The next dispatch reads this one's last level through its image.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace

void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint texture) {
    make_mipmaps_together(programs, {texture});
}

void make_box_mipmaps(const ocean::ProgramFactory& programs, GLuint first, GLuint second) {
    make_mipmaps_together(programs, {first, second});
}

}  // namespace step05
