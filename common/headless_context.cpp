// A headless context's framebuffer (headless_context.hpp).
#include "common/headless_context.hpp"

#include "common/error.hpp"

#include <string>

namespace ocean {

void HeadlessContext::make_target() {
    GLint max_side = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_side);
    if (size_.x > max_side || size_.y > max_side)
        throw Error("--size " + std::to_string(size_.x) + "x" + std::to_string(size_.y) +
                    " exceeds this GPU's limit of " + std::to_string(max_side) + " pixels a side");
    color_ = make_renderbuffer();
    renderbuffer_storage(color_, GL_RGBA8, size_.x, size_.y);
    depth_ = make_renderbuffer();
    renderbuffer_storage(depth_, GL_DEPTH24_STENCIL8, size_.x, size_.y);
    framebuffer_ = make_framebuffer();
    attach_renderbuffer(framebuffer_, GL_COLOR_ATTACHMENT0, color_);
    if (!attach_renderbuffer(framebuffer_, GL_DEPTH_STENCIL_ATTACHMENT, depth_))
        throw Error("the offscreen framebuffer of " + std::to_string(size_.x) + "x" + std::to_string(size_.y) +
                    " is incomplete (too large for this GPU?)");
}

void HeadlessContext::release_target() {
    color_.reset();
    depth_.reset();
    framebuffer_.reset();
}

}  // namespace ocean
