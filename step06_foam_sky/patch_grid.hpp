// The patches the tessellator cuts: count x count squares of side `size` centred on the origin,
// four corners each (GL_PATCHES of 4 vertices). ocean.vert moves the whole grid with the camera.
#pragma once

#include "common/gl.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/patch_view.hpp"

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace step06 {

class PatchGrid {
public:
    // The shaders that draw it into the G-buffer: the tessellation pipeline.
    static std::vector<std::string> mesh_shaders() {
        return {"step06_foam_sky/shaders/ocean.vert", "step06_foam_sky/shaders/ocean.tesc",
                "step06_foam_sky/shaders/ocean.tese", "step06_foam_sky/shaders/ocean.frag"};
    }

    // Called when patch_count or tess_patch_size changed (their Generation).
    void build(int count, float size) {
        std::vector<glm::vec2> corners;
        const float half = 0.5f * float(count) * size;
        for (int j = 0; j < count; ++j)
            for (int i = 0; i < count; ++i) {
                const glm::vec2 p(float(i) * size - half, float(j) * size - half);
                corners.insert(corners.end(), {p, p + glm::vec2(size, 0), p + glm::vec2(size, size), p + glm::vec2(0, size)});
            }
        vertices_ = ocean::make_buffer();
        ocean::buffer_data(vertices_, GLsizeiptr(corners.size() * sizeof(glm::vec2)), corners.data(), GL_STATIC_DRAW);
        vao_ = ocean::make_vertex_array();
        ocean::vertex_attribute(vao_, 0, vertices_, 2, sizeof(glm::vec2));
        count_ = count;
    }

    // Every patch, with `mesh` in use: the control shader culls and cuts them (the triangles'
    // edges only when `wireframe`). Returns how many patches were sent.
    int draw(const ocean::ShaderProgram& /*mesh*/, const PatchView& /*view*/, float /*tess_scale*/, bool wireframe) const {
        glBindVertexArray(vao_.id());
        glPatchParameteri(GL_PATCH_VERTICES, 4);
        if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glDrawArrays(GL_PATCHES, 0, 4 * count_ * count_);
        if (wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        return count_ * count_;
    }

    int patch_count() const { return count_ * count_; }

private:
    ocean::Buffer vertices_;
    ocean::VertexArray vao_;
    int count_ = 0;
};

}  // namespace step06
