#include "step06_foam_sky/gbuffer.hpp"

#include "common/gl_texture.hpp"

namespace step06 {

void GBuffer::resize(glm::ivec2 size, GLuint depth) {
    if ((size == size_ && depth == depth_) || size.x <= 0 || size.y <= 0) return;
    size_ = size;
    depth_ = depth;
    // Read with texelFetch only: nearest, one level (an integer texture with GL's default
    // mipmap-linear filter would be incomplete and read as zero).
    world_ = ocean::make_float_texture_2d(GL_RGBA32F, size.x, size.y);
    rest_ = ocean::make_float_texture_2d(GL_RGBA32UI, size.x, size.y);
    target_ = ocean::make_framebuffer();
    ocean::attach_texture_2d(target_, GL_COLOR_ATTACHMENT0, world_);
    ocean::attach_texture_2d(target_, GL_COLOR_ATTACHMENT1, rest_);
    ocean::attach_texture_2d(target_, GL_DEPTH_ATTACHMENT, depth);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    ocean::draw_buffers(target_, 2, buffers);
}

void GBuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
    glViewport(0, 0, size_.x, size_.y);
}

}  // namespace step06
