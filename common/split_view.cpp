#include "common/split_view.hpp"

#include "common/text.hpp"

#include <imgui.h>

#include <algorithm>
#include <iostream>

namespace ocean {

int SplitView::divide(int width) const {
    if (!divide_ || width < 3) return width / 2;
    return std::clamp(*divide_, 1, width - 1);
}

std::optional<std::string> SplitView::render(ParamRegistry& params, const SplitVariants& variants, glm::ivec2 size,
                                             GLuint target, const std::function<void()>& render_frame) {
    // The parameters either variant sets, as they are now.
    std::vector<std::pair<Param*, ParamValue>> saved;
    for (const auto* side : {&variants.left, &variants.right})
        for (const auto& assignment : *side)
            if (Param* p = params.find(trim(assignment.substr(0, assignment.find('=')))))
                saved.emplace_back(p, p->value());
    std::optional<std::string> message;
    // Which side is which, said once where the picture cannot (headless runs, the panel hidden).
    const std::string labels = "split view: left " + variants.left_label + " | right " + variants.right_label;
    if (labels != printed_labels_) {
        std::cout << labels << "\n";
        printed_labels_ = labels;
    }
    if (size_ != size) {
        colour_ = make_renderbuffer();
        renderbuffer_storage(colour_, GL_RGBA8, size.x, size.y);
        left_half_ = make_framebuffer();
        attach_renderbuffer(left_half_, GL_COLOR_ATTACHMENT0, colour_);
        size_ = size;
    }
    const int middle = divide(size.x);
    divide_.reset();
    last_divide_ = middle;
    for (int side = 0; side < 2; ++side) {
        for (const auto& assignment : side == 0 ? variants.left : variants.right)
            if (auto error = params.set_assignment(assignment)) message = "split view: " + *error;
        render_frame();
        // The left variant's left part is kept aside, then copied over the right variant's frame.
        if (side == 0) copy_colour(target, left_half_.id(), middle, size.y);
        else copy_colour(left_half_.id(), target, middle, size.y);
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

void draw_split_labels(const SplitVariants& variants, float divide) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const float bottom = ImGui::GetIO().DisplaySize.y - 8;
    const auto label = [&](const std::string& text, float x, float row) {
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        const ImVec2 at(x, bottom - size.y - row * (size.y + 6));
        draw->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2),
                            IM_COL32(0, 0, 0, 160), 3);
        draw->AddText(at, IM_COL32(255, 255, 255, 255), text.c_str());
    };
    // Each against its side of the line: the left one ends 8 pixels before it, the right one starts after.
    const float left_width = ImGui::CalcTextSize(variants.left_label.c_str()).x;
    // A left half too narrow for its label: the label goes a row up, clear of the right one.
    const float left_x = divide - 8 - left_width;
    label(variants.left_label, std::max(4.0f, left_x), left_x < 4 ? 1.0f : 0.0f);
    label(variants.right_label, divide + 8, 0);
}

}  // namespace ocean
