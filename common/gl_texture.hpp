// 2D textures that passes render into, in each profile (gl.hpp's pattern: GL 4.5 edits an object
// by its name, GL 4.1 and ES 3.0 bind it to edit it and put back what was bound). The fragment
// passes that stand in for compute shaders where there are none (step05's fragment FFT) keep
// their data in these: one texel a value, read with texelFetch, written as a colour attachment.
#pragma once

#include "common/gl.hpp"

namespace ocean {

namespace detail {
// Binds a 2D texture to the active unit for one edit; puts back the one bound there before.
class BindTexture2dForEdit {
public:
    explicit BindTexture2dForEdit(GLuint id) : before_(bound(GL_TEXTURE_BINDING_2D)) { glBindTexture(GL_TEXTURE_2D, id); }
    ~BindTexture2dForEdit() { glBindTexture(GL_TEXTURE_2D, before_); }
    BindTexture2dForEdit(const BindTexture2dForEdit&) = delete;
    BindTexture2dForEdit& operator=(const BindTexture2dForEdit&) = delete;

private:
    GLuint before_;
};

// The format and type glTexImage2D is given with each float `format` (GL 4.1 has no glTexStorage).
inline void float_upload_format(GLenum format, GLenum& upload_format, GLenum& type) {
    type = format == GL_RGBA16F || format == GL_RG16F || format == GL_R16F ? GL_HALF_FLOAT : GL_FLOAT;
    upload_format = format == GL_RGBA32F || format == GL_RGBA16F ? GL_RGBA : format == GL_RG32F || format == GL_RG16F ? GL_RG : GL_RED;
}
}  // namespace detail

// A 2D texture of `width` x `height` texels of a float `format` (GL_RGBA32F, GL_RG32F, GL_R32F or
// their 16-bit forms), one level, read texel by texel (nearest, no mipmaps: complete in every
// profile), edges clamped.
inline Texture make_float_texture_2d(GLenum format, GLsizei width, GLsizei height) {
    Texture texture = make_texture(GL_TEXTURE_2D);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTexture2dForEdit edit(texture.id());
    GLenum upload_format = 0, type = 0;
    detail::float_upload_format(format, upload_format, type);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), width, height, 0, upload_format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
#else
    glTextureStorage2D(texture.id(), 1, format, width, height);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
#endif
    return texture;
}

// Replaces the whole of level 0 of a float texture made by make_float_texture_2d with `data`
// (`width` x `height` texels of 4, 2 or 1 floats, as its format has channels).
inline void upload_float_texture_2d(const Texture& texture, GLenum format, GLsizei width, GLsizei height,
                                    const float* data) {
    GLenum upload_format = 0, type = 0;
    detail::float_upload_format(format, upload_format, type);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTexture2dForEdit edit(texture.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, upload_format, GL_FLOAT, data);
#else
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, upload_format, GL_FLOAT, data);
#endif
}

// Attaches level 0 of a 2D texture to a framebuffer at `attachment`; returns whether the
// framebuffer is complete afterwards (rendering to 32-bit floats needs EXT_color_buffer_float in ES).
inline bool attach_texture_2d(const Framebuffer& framebuffer, GLenum attachment, const Texture& texture) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.id(), 0);
    return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#else
    glNamedFramebufferTexture(framebuffer.id(), attachment, texture.id(), 0);
    return glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#endif
}

}  // namespace ocean
