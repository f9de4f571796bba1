// The bodies' meshes: a unit cube (sides 1, scaled to a box), a unit-diameter sphere and a unit
// hull (hull_half_beam's sections lofted, with its deck), with normals, drawn by
// shaders/body.vert and body.frag.
#pragma once

#include "common/gl.hpp"
#include "step07_buoyancy/floating_body.hpp"

#include <vector>

namespace step07 {

class BodyMeshes {
public:
    BodyMeshes();
    // Draws `kind`'s mesh with the bound program (its model matrix already set).
    void draw(ShapeKind kind) const;

private:
    struct Mesh {
        ocean::Buffer vertices;
        ocean::VertexArray vao;
        int count = 0;
    };
    static Mesh upload(const std::vector<glm::vec3>& positions_and_normals);
    static std::vector<glm::vec3> hull_triangles();
    Mesh cube_, sphere_, hull_;
};

}  // namespace step07
