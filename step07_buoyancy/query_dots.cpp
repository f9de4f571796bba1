#include "step07_buoyancy/query_dots.hpp"

namespace step07 {

void QueryDots::draw(const std::vector<glm::dvec3>& dots, glm::dvec3 origin, const glm::mat4& view_projection) {
    if (dots.empty()) return;
    ocean::ShaderProgram* p = programs_("query_points", {"step07_buoyancy/shaders/query_points.vert",
                                                         "step07_buoyancy/shaders/query_points.frag"}, {});
    if (p == nullptr) return;
    std::vector<glm::vec3> positions;
    for (const auto& d : dots) positions.emplace_back(d - origin);  // small floats anywhere on the ocean
    buffer_ = ocean::make_buffer();
    glNamedBufferStorage(buffer_.id(), GLsizeiptr(positions.size() * sizeof(glm::vec3)), positions.data(), 0);
    if (vao_.id() == 0) {
        vao_ = ocean::make_vertex_array();
        glEnableVertexArrayAttrib(vao_.id(), 0);
        glVertexArrayAttribFormat(vao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao_.id(), 0, 0);
    }
    glVertexArrayVertexBuffer(vao_.id(), 0, buffer_.id(), 0, sizeof(glm::vec3));
    p->set("u_view_projection", view_projection);
    glUseProgram(p->id());
    glEnable(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_POINTS, 0, GLsizei(positions.size()));
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace step07
