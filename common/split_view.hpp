// The split view, a framework service a step opts into with App::offer_split_view: the whole frame
// is rendered once per variant (the step's render() runs twice a frame, each time with that
// variant's parameters set), the left half of the first is kept and put over the second, and the
// parameters the variants set are put back as they were (their values kept typed: nothing else
// is touched). Work that must happen once a
// frame, whatever is shown (advancing a simulation, accumulating foam), belongs in update(),
// which runs once before the frame's renders.
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
};

class SplitView {
public:
    // Renders `render_frame` once per variant into `target` (of `size`), composed left | right.
    // Returns the message for a variant assignment the registry refuses (the frame is still drawn).
    std::optional<std::string> render(ParamRegistry& params, const SplitVariants& variants, glm::ivec2 size,
                                      GLuint target, const std::function<void()>& render_frame);

private:
    Renderbuffer colour_;
    Framebuffer left_half_;
    glm::ivec2 size_{0};
};

}  // namespace ocean
