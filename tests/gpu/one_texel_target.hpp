// A 1 x 1 colour target bound for as long as the object lives, the previous framebuffer bound
// again after. For GPU tests that draw with the rasteriser off (transform feedback, primitive
// queries): nothing is drawn, but a draw needs a complete framebuffer all the same, and the
// tests' surfaceless context has none of its own (NVIDIA's driver refuses such a draw with
// GL_INVALID_FRAMEBUFFER_OPERATION; llvmpipe lets it through).
#pragma once

#include "common/gl.hpp"

namespace ocean_test {

class OneTexelTarget {
public:
    OneTexelTarget() {
        glTextureStorage2D(colour_.id(), 1, GL_RGBA8, 1, 1);
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, colour_.id(), 0);
        glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    }
    ~OneTexelTarget() { glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_)); }
    OneTexelTarget(const OneTexelTarget&) = delete;
    OneTexelTarget& operator=(const OneTexelTarget&) = delete;

private:
    ocean::Texture colour_ = ocean::make_texture(GL_TEXTURE_2D);
    ocean::Framebuffer framebuffer_ = ocean::make_framebuffer();
    GLint previous_ = 0;
};

}  // namespace ocean_test
