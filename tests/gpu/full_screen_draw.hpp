// For GPU tests that evaluate a fragment shader over a grid: draws `program` (its uniforms and
// textures already set) with one full-screen triangle into a new width x height target of
// `format`, and reads the target back as `pixel_format` values of type T, `components` a texel
// (GL_FLOAT with float, GL_UNSIGNED_BYTE with std::uint8_t). The test context's framebuffer and
// viewport are restored after.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"

#include <cstddef>
#include <vector>

namespace ocean_test {

template <typename T>
std::vector<T> draw_full_screen(const ocean::ShaderProgram& program, int width, int height, GLenum format,
                                GLenum pixel_format, GLenum type, int components) {
    ocean::Texture target = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(target.id(), 1, format, width, height);
    ocean::Framebuffer fbo = ocean::make_framebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    ocean::VertexArray vao = ocean::make_vertex_array();
    GLint previous_framebuffer = 0, previous_viewport[4] = {};
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);
    glGetIntegerv(GL_VIEWPORT, previous_viewport);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, width, height);
    glUseProgram(program.id());
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<T> texels(std::size_t(width) * std::size_t(height) * std::size_t(components));
    glGetTextureImage(target.id(), 0, pixel_format, type, GLsizei(texels.size() * sizeof(T)), texels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_framebuffer));
    glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);
    return texels;
}

}  // namespace ocean_test
