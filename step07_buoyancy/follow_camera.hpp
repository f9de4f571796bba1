// The camera kept on the boat: each frame the view's target moves as the boat moved along the
// water (x, z), so the boat stays where it is in the picture wherever it sails, and the angles and
// the distance stay the user's (drag, wheel). Without it a boat under way leaves the view in
// seconds. On from the start; `follow_boat` turns it off and on.
#pragma once

#include "common/camera.hpp"
#include "common/params.hpp"

#include <glm/vec3.hpp>

namespace step07 {

class FollowCamera {
public:
    void declare(ocean::ParamRegistry& p) {
        p.add_bool("follow_boat", &on_, "the camera keeps the boat where it is in the view");
    }
    bool on() const { return on_; }
    // After a step that moved the boat from `before` to `now` (positions in the world, metres).
    void follow(ocean::Camera& camera, glm::dvec3 before, glm::dvec3 now) const {
        if (on_) camera.target += glm::dvec3(now.x - before.x, 0.0, now.z - before.z);
    }

private:
    bool on_ = true;
};

}  // namespace step07
