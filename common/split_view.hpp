// The split view, a framework service a step opts into by returning its two variants from
// App::split_variants(): the whole frame is rendered once per variant (the step's render() runs
// twice a frame, each time with that variant's parameters set), the left half of the first is
// kept and put over the second, and the parameters are restored. Work that must happen once a
// frame, whatever is shown (advancing a simulation, accumulating foam), belongs in update(),
// which runs once before the frame's renders.
#pragma once

#include "common/gl.hpp"
#include "common/params.hpp"

#include <glm/vec2.hpp>

#include <functional>
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
    // A variant assignment the registry refuses is reported in *message.
    void render(ParamRegistry& params, const SplitVariants& variants, glm::ivec2 size, GLuint target,
                const std::function<void()>& render_frame, std::string* message);

private:
    Renderbuffer colour_;
    Framebuffer left_half_;
    glm::ivec2 size_{0};
};

}  // namespace ocean
