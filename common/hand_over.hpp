// Previous/Next, "handing over": a step ends and the neighbouring step replaces this process, at
// the same moment, size and view, paused if it was. The camera travels as `--carry name=value`,
// which the next step applies only if it has that parameter (a 2D step has no camera), so no step
// needs to know another.
#pragma once

#include "common/params.hpp"

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace ocean {

// The executable of `step`, built beside this one (build/<preset>/<step>/<step>), or "".
std::string step_executable(const std::string& step);

// The command line that starts `executable` where this step is: --start-at, --size, the camera
// parameters this step has (its kCameraGroup, as --carry), --split, --paused.
std::vector<std::string> hand_over_command(const std::string& executable, double time, glm::ivec2 size,
                                         const ParamRegistry& params, bool split, bool paused);

// Replaces this process with `command` once the step is gone, or returns status.
int run_next_step(int status, const std::vector<std::string>& command);

// Every step of the repository, in order (CMake's list: the stepNN_* folders it builds).
std::vector<std::string> repository_steps();

}  // namespace ocean
