// Float textures that passes render into, in each profile (gl.hpp's pattern: GL 4.5 edits an object
// by its name, GL 4.1 and ES 3.0 bind it to edit it and put back what was bound). The fragment
// passes that stand in for compute shaders where there are none (step05's fragment FFT) keep
// their data in these: one texel a value, read with texelFetch, written as a colour attachment.
#pragma once

#include "common/gl.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace ocean {

namespace detail {
// Binds a texture to `target` (GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY or GL_TEXTURE_CUBE_MAP) of the active unit for one
// edit; puts back the one bound there before.
class BindTextureForEdit {
public:
    BindTextureForEdit(GLenum target, GLuint id)
        : target_(target),
          before_(bound(target == GL_TEXTURE_2D_ARRAY    ? GL_TEXTURE_BINDING_2D_ARRAY
                        : target == GL_TEXTURE_CUBE_MAP ? GL_TEXTURE_BINDING_CUBE_MAP
                                                        : GL_TEXTURE_BINDING_2D)) {
        glBindTexture(target_, id);
    }
    ~BindTextureForEdit() { glBindTexture(target_, before_); }
    BindTextureForEdit(const BindTextureForEdit&) = delete;
    BindTextureForEdit& operator=(const BindTextureForEdit&) = delete;

private:
    GLenum target_;
    GLuint before_;
};

// The format and type glTexImage2D is given with each `format` (GL 4.1 has no glTexStorage, and
// ES 3.0 accepts only these pairs).
inline void upload_format_of(GLenum format, GLenum& upload_format, GLenum& type) {
    if (format == GL_RGBA32UI) {
        upload_format = GL_RGBA_INTEGER;
        type = GL_UNSIGNED_INT;
        return;
    }
    if (format == GL_DEPTH_COMPONENT32F) {
        upload_format = GL_DEPTH_COMPONENT;
        type = GL_FLOAT;
        return;
    }
    type = format == GL_RGBA16F || format == GL_RG16F || format == GL_R16F ? GL_HALF_FLOAT : GL_FLOAT;
    upload_format = format == GL_RGBA32F || format == GL_RGBA16F ? GL_RGBA : format == GL_RG32F || format == GL_RG16F ? GL_RG : GL_RED;
}
}  // namespace detail

// A 2D texture of `width` x `height` texels of a float `format` (GL_RGBA32F, GL_RG32F, GL_R32F or
// their 16-bit forms), one level, read texel by texel (nearest, no mipmaps: complete in every
// profile), edges clamped. Also for what one pass writes and the next reads texel by texel:
// GL_RGBA32UI (bits a shader packed) and GL_DEPTH_COMPONENT32F (a depth buffer).
inline Texture make_float_texture_2d(GLenum format, GLsizei width, GLsizei height) {
    Texture texture = make_texture(GL_TEXTURE_2D);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D, texture.id());
    GLenum upload_format = 0, type = 0;
    detail::upload_format_of(format, upload_format, type);
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
    detail::upload_format_of(format, upload_format, type);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D, texture.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, upload_format, GL_FLOAT, data);
#else
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, upload_format, GL_FLOAT, data);
#endif
}

// Whether 32-bit float textures may be sampled with linear filtering and mipmaps (the simulation's
// maps are): always in desktop GL, only with OES_texture_float_linear in ES 3.0 and WebGL 2.
inline bool float_textures_filterable() {
#if defined(OCEAN_GL_ES)
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name != nullptr && std::string_view(name) == "GL_OES_texture_float_linear") return true;
    }
    return false;
#else
    return true;
#endif
}

// Attaches level 0 of a 2D texture (by name: one another part owns, such as a shared depth
// buffer) to a framebuffer at `attachment`; returns whether the framebuffer is complete afterwards
// (rendering to 32-bit floats needs EXT_color_buffer_float in ES).
inline bool attach_texture_2d(const Framebuffer& framebuffer, GLenum attachment, GLuint texture) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
    return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#else
    glNamedFramebufferTexture(framebuffer.id(), attachment, texture, 0);
    return glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#endif
}
inline bool attach_texture_2d(const Framebuffer& framebuffer, GLenum attachment, const Texture& texture) {
    return attach_texture_2d(framebuffer, attachment, texture.id());
}

// What a pass that draws into textures changes, kept while it lives and put back after: the draw
// framebuffer, the program in use, the vertex array (it binds `vertex_array`: an empty one, for
// full-screen triangles whose corners come from gl_VertexID), the viewport, and the tests that
// would keep a fragment from its texel (blending, the depth and scissor tests, face culling: all
// off while it lives) and the colour mask (all channels written).
class OffscreenPassState {
public:
    explicit OffscreenPassState(GLuint vertex_array)
        : framebuffer_(GL_DRAW_FRAMEBUFFER, 0), program_(GL_CURRENT_PROGRAM, 0),
          vertex_array_(GL_VERTEX_ARRAY_BINDING, vertex_array) {
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask_);
        for (std::size_t i = 0; i < kTests.size(); ++i) {
            enabled_[i] = glIsEnabled(kTests[i]);
            glDisable(kTests[i]);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    ~OffscreenPassState() {
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        for (std::size_t i = 0; i < kTests.size(); ++i)
            if (enabled_[i]) glEnable(kTests[i]);
        glColorMask(colour_mask_[0], colour_mask_[1], colour_mask_[2], colour_mask_[3]);
    }
    OffscreenPassState(const OffscreenPassState&) = delete;
    OffscreenPassState& operator=(const OffscreenPassState&) = delete;

private:
    static constexpr std::array<GLenum, 4> kTests{GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST, GL_CULL_FACE};
    detail::BindForEdit framebuffer_, program_, vertex_array_;
    std::array<GLboolean, 4> enabled_{};
    GLboolean colour_mask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLint viewport_[4] = {0, 0, 0, 0};
};

// A 2D array texture of `layers` maps of `size` x `size` texels of a float `format` with `levels`
// mip levels (1 for none): the simulation's maps, one layer a cascade, as the renderer samples
// them (linear between texels and levels, repeating: a map is one tile of an endless sea).
// Sampling 32-bit floats with filtering needs OES_texture_float_linear in ES.
inline Texture make_map_texture_2d_array(GLenum format, GLsizei size, GLsizei layers, GLsizei levels) {
    Texture texture = make_texture(GL_TEXTURE_2D_ARRAY);
    const GLenum min_filter = levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR;
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D_ARRAY, texture.id());
    GLenum upload_format = 0, type = 0;
    detail::upload_format_of(format, upload_format, type);
    for (GLint level = 0; level < levels; ++level) {  // a level at a time: GL 4.1 has no glTexStorage
        const GLsizei side = std::max<GLsizei>(1, size >> level);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, level, GLint(format), side, side, layers, 0, upload_format, type, nullptr);
    }
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GLint(min_filter));
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
#else
    glTextureStorage3D(texture.id(), levels, format, size, size, layers);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GLint(min_filter));
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
#endif
    return texture;
}

// Attaches level `level` of layer `layer` of a 2D array texture to a framebuffer at `attachment`;
// returns whether the framebuffer is complete afterwards.
inline bool attach_texture_layer(const Framebuffer& framebuffer, GLenum attachment, const Texture& texture,
                                 GLint level, GLint layer) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, attachment, texture.id(), level, layer);
    return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#else
    glNamedFramebufferTextureLayer(framebuffer.id(), attachment, texture.id(), level, layer);
    return glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#endif
}

// Levels 1 and below of a texture (`target`: GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP, ...) from
// its level 0: what step05's box_mip.comp makes where there are compute shaders. The
// specification recommends, without requiring, that each texel be the mean of the 2 x 2 it covers;
// the drivers we know do that for a power-of-two texture (the portable GPU tests check it on the
// one they run on).
inline void generate_mipmaps(const Texture& texture, GLenum target) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(target, texture.id());
    glGenerateMipmap(target);
#else
    (void)target;  // a texture made by glCreateTextures knows its target
    glGenerateTextureMipmap(texture.id());
#endif
}

// A float texture read with linear filtering, one level, its edges `wrap_s` and `wrap_t`
// (GL_REPEAT or GL_CLAMP_TO_EDGE): a table a shader interpolates (step06's horizon, one row) or an
// image (an equirectangular sky). `format` as make_float_texture_2d's; `data` may be null.
inline Texture make_linear_float_texture_2d(GLenum format, GLsizei width, GLsizei height, GLenum wrap_s, GLenum wrap_t,
                                            const float* data = nullptr) {
    Texture texture = make_float_texture_2d(format, width, height);
    if (data != nullptr) upload_float_texture_2d(texture, format, width, height, data);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D, texture.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap_t));
#else
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GLint(wrap_s));
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GLint(wrap_t));
#endif
    return texture;
}

// A cubemap of six `size` x `size` faces of a float `format` with `levels` mip levels, trilinear:
// a sky that passes render into face by face and shaders sample by direction. Seamless across
// faces (core in ES; GL asks for it).
inline Texture make_cube_texture(GLenum format, GLsizei size, GLsizei levels) {
    Texture texture = make_texture(GL_TEXTURE_CUBE_MAP);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_CUBE_MAP, texture.id());
    GLenum upload_format = 0, type = 0;
    detail::upload_format_of(format, upload_format, type);
    for (GLint level = 0; level < levels; ++level)  // a level at a time: GL 4.1 has no glTexStorage
        for (GLenum face = 0; face < 6; ++face) {
            const GLsizei side = std::max<GLsizei>(1, size >> level);
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, GLint(format), side, side, 0, upload_format, type,
                         nullptr);
        }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
#else
    glTextureStorage2D(texture.id(), levels, format, size, size);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
#endif
#if !defined(OCEAN_GL_ES)
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
#endif
    return texture;
}

// Attaches level 0 of cubemap face `face` (0 to 5: +X, -X, +Y, -Y, +Z, -Z) to a framebuffer at
// `attachment`; returns whether the framebuffer is complete afterwards.
inline bool attach_cube_face(const Framebuffer& framebuffer, GLenum attachment, const Texture& texture, int face) {
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), texture.id(), 0);
    return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#else
    glNamedFramebufferTextureLayer(framebuffer.id(), attachment, texture.id(), 0, face);  // a cube's layers: its faces
    return glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
#endif
}

// Binds `texture` to `target` of texture unit `unit` (glBindTextureUnit where GL has it); the
// active unit is left at 0, where the bind-to-edit helpers expect it.
inline void bind_texture(GLuint unit, GLenum target, GLuint texture) {
#if OCEAN_GL_BIND_TO_EDIT
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target, texture);
    glActiveTexture(GL_TEXTURE0);
#else
    (void)target;  // a texture made by glCreateTextures knows its target
    glBindTextureUnit(unit, texture);
#endif
}

// An 8-bit RGBA image as a 2D texture, one level, nearest (a figure the panel or a view shows);
// rgba null: no image yet, a picture to draw into.
inline Texture make_colour_texture_2d(GLsizei width, GLsizei height, const void* rgba) {
    Texture texture = make_texture(GL_TEXTURE_2D);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
#else
    glTextureStorage2D(texture.id(), 1, GL_RGBA8, width, height);
    if (rgba != nullptr) glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
#endif
    return texture;
}

// An 8-bit RGBA image that tiles (a pattern laid over a surface): mipmapped from it, trilinear,
// repeating both ways.
inline Texture make_tiling_colour_texture_2d(GLsizei width, GLsizei height, const void* rgba) {
    GLsizei levels = 1;
    while (std::max(width, height) >> levels) ++levels;
    Texture texture = make_texture(GL_TEXTURE_2D);
#if OCEAN_GL_BIND_TO_EDIT
    detail::BindTextureForEdit edit(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
#else
    glTextureStorage2D(texture.id(), levels, GL_RGBA8, width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateTextureMipmap(texture.id());
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
#endif
    return texture;
}

#if OCEAN_GL_BIND_TO_EDIT
namespace detail {
// Layers first_layer .. first_layer + layers - 1 of level `level` of a float RGBA 2D array texture
// (`side` x `side` texels a layer), read through a framebuffer, one after the other, to
// `destination`: an address in client memory, or with a buffer bound to GL_PIXEL_PACK_BUFFER a
// byte offset in it (glReadPixels then only queues the copy). Where GL has no glGetTexImage (ES)
// and no glGetTextureImage (GL 4.1).
inline void read_layers(GLuint texture, GLint level, GLint first_layer, GLsizei layers, GLsizei side,
                        std::uintptr_t destination) {
    const std::uintptr_t layer_bytes = std::uintptr_t(side) * std::uintptr_t(side) * 4 * sizeof(float);
    GLuint reader = 0;
    glGenFramebuffers(1, &reader);
    {
        const BindForEdit edit(GL_READ_FRAMEBUFFER, reader);
        for (GLint i = 0; i < layers; ++i) {
            glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture, level, first_layer + i);
            glReadPixels(0, 0, side, side, GL_RGBA, GL_FLOAT,
                         reinterpret_cast<void*>(destination + std::uintptr_t(i) * layer_bytes));
        }
    }
    glDeleteFramebuffers(1, &reader);
}
}  // namespace detail
#endif

// Level `level` (`side` x `side` texels) of layer `layer` of a float RGBA 2D array texture, read
// back to the CPU: through a framebuffer where GL cannot read a texture directly (ES has no
// glGetTexImage). Row major, 4 floats a texel.
inline std::vector<float> read_texture_layer(GLuint texture, GLint level, GLint layer, GLsizei side) {
    std::vector<float> texels(std::size_t(side) * std::size_t(side) * 4);
#if OCEAN_GL_BIND_TO_EDIT
    detail::read_layers(texture, level, layer, 1, side, reinterpret_cast<std::uintptr_t>(texels.data()));
#else
    glGetTextureSubImage(texture, level, 0, 0, layer, side, side, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(texels.size() * sizeof(float)), texels.data());
#endif
    return texels;
}

// Queues a copy of level 0 of every layer of a 2D array texture of RGBA floats (`side` x `side`
// texels a layer) into `buffer` from byte `offset`, layer after layer, and returns at once: the
// copy runs when the GPU gets there (a fence after it says when; read_buffer then reads it).
// GL 4.5 copies the texture by name; GL 4.1 and ES 3.0 read each layer through a framebuffer.
inline void queue_layers_into_buffer(GLuint texture, GLsizei side, GLsizei layers, const Buffer& buffer, GLintptr offset) {
    // With a buffer bound to GL_PIXEL_PACK_BUFFER the "pointer" is an offset into it.
    const detail::BindForEdit pack(GL_PIXEL_PACK_BUFFER, buffer.id());
#if OCEAN_GL_BIND_TO_EDIT
    detail::read_layers(texture, 0, 0, layers, side, std::uintptr_t(offset));
#else
    const GLsizeiptr bytes = GLsizeiptr(side) * side * 4 * GLsizeiptr(sizeof(float)) * layers;
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(bytes), reinterpret_cast<void*>(offset));
#endif
}

}  // namespace ocean
