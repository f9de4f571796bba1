// Runs a program's vertex shader over every vertex of a grid, once each (GL_POINTS, rasteriser
// off), and returns what transform feedback captured: `floats_per_vertex` floats a vertex, in
// the order of the program's feedback varyings.
#pragma once

#include "common/grid.hpp"
#include "common/shader.hpp"
#include "tests/gpu/one_texel_target.hpp"

#include <vector>

namespace ocean_test {

inline std::vector<float> capture_vertices(const ocean::ShaderProgram& program, const ocean::GridMesh& grid,
                                           int floats_per_vertex) {
    const std::size_t count = std::size_t(grid.vertex_count());
    ocean::Buffer captured = ocean::make_buffer();
    glNamedBufferStorage(captured.id(), GLsizeiptr(count * floats_per_vertex * sizeof(float)), nullptr, 0);
    const OneTexelTarget target;  // a draw needs a framebuffer, rasterised or not
    glUseProgram(program.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured.id());
    glBeginTransformFeedback(GL_POINTS);
    glBindVertexArray(grid.vertex_array());
    glDrawArrays(GL_POINTS, 0, GLsizei(count));
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    std::vector<float> out(count * floats_per_vertex);
    glGetNamedBufferSubData(captured.id(), 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
    return out;
}

}  // namespace ocean_test
