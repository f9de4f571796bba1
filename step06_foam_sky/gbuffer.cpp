#include "step06_foam_sky/gbuffer.hpp"

namespace step06 {

void GBuffer::resize(glm::ivec2 size, GLuint depth) {
    if ((size == size_ && depth == depth_) || size.x <= 0 || size.y <= 0) return;
    size_ = size;
    depth_ = depth;
    world_ = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(world_.id(), 1, GL_RGBA32F, size.x, size.y);
    rest_ = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(rest_.id(), 1, GL_RGBA32UI, size.x, size.y);
    // Read with texelFetch only; an integer texture is incomplete (reads as zero) with GL's
    // default mipmap-linear filter, so both are set to nearest.
    for (GLuint t : {world_.id(), rest_.id()}) {
        glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    target_ = ocean::make_framebuffer();
    glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT0, world_.id(), 0);
    glNamedFramebufferTexture(target_.id(), GL_COLOR_ATTACHMENT1, rest_.id(), 0);
    glNamedFramebufferTexture(target_.id(), GL_DEPTH_ATTACHMENT, depth, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(target_.id(), 2, buffers);
}

void GBuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
    glViewport(0, 0, size_.x, size_.y);
}

}  // namespace step06
