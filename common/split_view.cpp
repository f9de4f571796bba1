#include "common/split_view.hpp"

#include "common/text.hpp"

namespace ocean {

std::optional<std::string> SplitView::render(ParamRegistry& params, const SplitVariants& variants, glm::ivec2 size,
                                             GLuint target, const std::function<void()>& render_frame) {
    // The parameters either variant sets, as they are now.
    std::vector<std::pair<Param*, ParamValue>> saved;
    for (const auto* side : {&variants.left, &variants.right})
        for (const auto& assignment : *side)
            if (Param* p = params.find(trim(assignment.substr(0, assignment.find('=')))))
                saved.emplace_back(p, p->value());
    std::optional<std::string> message;
    if (size_ != size) {
        colour_ = make_renderbuffer();
        glNamedRenderbufferStorage(colour_.id(), GL_RGBA8, size.x, size.y);
        left_half_ = make_framebuffer();
        glNamedFramebufferRenderbuffer(left_half_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
        size_ = size;
    }
    const int middle = size.x / 2;
    for (int side = 0; side < 2; ++side) {
        for (const auto& assignment : side == 0 ? variants.left : variants.right)
            if (auto error = params.set_assignment(assignment)) message = "split view: " + *error;
        render_frame();
        if (side == 0)
            glBlitNamedFramebuffer(target, left_half_.id(), 0, 0, middle, size.y, 0, 0, middle, size.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
        else
            glBlitNamedFramebuffer(left_half_.id(), target, 0, 0, middle, size.y, 0, 0, middle, size.y,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
        for (auto it = saved.rbegin(); it != saved.rend(); ++it) it->first->store(it->second);
    }
    // A thin white line between the halves.
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glEnable(GL_SCISSOR_TEST);
    glScissor(middle - 1, 0, 2, size.y);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    return message;
}

}  // namespace ocean
