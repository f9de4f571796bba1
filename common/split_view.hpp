// The split view, a framework service a step opts into with App::offer_split_view: the whole frame
// is rendered once per variant (the step's render() runs twice a frame, each time with that
// variant's parameters set), the left half of the first is kept and put over the second, and the
// parameters the variants set are put back as they were (their values kept typed: nothing else
// is touched). Work that must happen once a
// frame, whatever is shown (advancing a simulation, accumulating foam), belongs in update(),
// which runs once before the frame's renders; variants that change what update() computes
// (update_each_side) have it run before each side's render instead.
#pragma once

#include "common/gl.hpp"
#include "common/params.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ocean {

struct SplitVariants {
    std::string left_label, right_label;
    std::vector<std::string> left, right;  // "name=value" each
    // The variants differ in what update() computes, not only in how it is drawn (a transform's
    // backend: each side's maps come from its own): update() runs before each side's render,
    // with that side's parameters, instead of once before both.
    bool update_each_side = false;
};

class SplitView {
public:
    // Where the next render() divides the halves, in pixels from the left: the panel sets it each
    // frame it is drawn (the middle of the part of the window it leaves free, so that both
    // variants show as much); a frame without it (no panel: headless runs, F1) divides at the
    // middle. Used once.
    void set_divide(int x) { divide_ = x; }
    // The divide of a target `width` wide: the one set, kept a pixel inside, or the middle.
    int divide(int width) const;
    // Where the halves were divided in the last render (0 before any).
    int last_divide() const { return last_divide_; }

    // Renders `render_frame` once per variant into `target` (of `size`), composed left | right.
    // Returns the message for a variant assignment the registry refuses (the frame is still drawn).
    std::optional<std::string> render(ParamRegistry& params, const SplitVariants& variants, glm::ivec2 size,
                                      GLuint target, const std::function<void()>& render_frame);

private:
    Renderbuffer colour_;
    Framebuffer left_half_;
    glm::ivec2 size_{0};
    std::optional<int> divide_;
    int last_divide_ = 0;
    std::string printed_labels_;  // the labels last told on stdout
};

// The variants' labels on the picture, at the bottom of each half, against the divide at `divide`
// (ImGui's coordinates), below the panel's default rectangle: drawn over everything, on a dark
// band, so that no window hides them.
void draw_split_labels(const SplitVariants& variants, float divide);

}  // namespace ocean
