// The bodies drawn into step06's scene: each body's mesh (body_mesh.hpp) placed by its position and
// orientation, lit as the sea is (the look's sun, the sky's reflection). Any program that floats
// step07's bodies draws them so.
#pragma once

#include "common/shader.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/sky.hpp"
#include "step07_buoyancy/body_mesh.hpp"
#include "step07_buoyancy/floating_body.hpp"

#include <glm/mat4x4.hpp>

#include <memory>
#include <vector>

namespace step07 {

class BodyPainter {
public:
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // The bodies, depth tested against the sea's depth in the bound framebuffer; positions from
    // `world_origin` (the sea's, near the camera) so that the floats stay small anywhere.
    void draw(const std::vector<FloatingBody>& bodies, glm::dvec3 world_origin, const glm::mat4& view_projection,
              glm::dvec3 eye, const step06::Sky& sky, const step06::LookParams& look);

private:
    ocean::ProgramFactory programs_;
    std::unique_ptr<BodyMeshes> meshes_;  // made on the first draw, when a GL context is current
};

}  // namespace step07
