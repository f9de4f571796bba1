// The camera as the sea's patches see it each frame, whichever way they are cut (patch_grid.hpp:
// by the tessellator; patch_lod.hpp: on the CPU).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace step06 {

// What a frame's patches need: the camera in metres from the sea's world origin, the grid's
// centre from that origin (the camera snapped to whole patches), and how far the waves can move
// a point (the culling boxes are widened by it). The tessellated grid reads them as uniforms
// (SeaRenderer sets them); the grid cut on the CPU (patch_lod.hpp) reads them itself.
struct PatchView {
    glm::mat4 view_projection;
    glm::vec3 eye;
    glm::vec2 grid_offset;
    float max_displacement;
};

}  // namespace step06
