// The full-screen triangle at the far plane (depth range 1..1), depth-tested with `test` against
// the mesh's depth and not writing it: GL_GREATER runs where the sea is (its shading), GL_LEQUAL
// where it is not (the sky behind it). `vao`: any vertex array (the triangle is made from
// gl_VertexID: common/shaders/fullscreen.vert).
#pragma once

#include "common/gl.hpp"

namespace step06 {

inline void draw_at_far_plane(GLenum test, GLuint vao) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(test);
    glDepthMask(GL_FALSE);
    glDepthRangef(1.0f, 1.0f);  // the float form: ES has only it
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthRangef(0.0f, 1.0f);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace step06
