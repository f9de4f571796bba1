#include "step07_buoyancy/body_mesh.hpp"

#include "common/constants.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace step07 {

BodyMeshes::Mesh BodyMeshes::upload(const std::vector<glm::vec3>& data) {
    Mesh m;
    m.vertices = ocean::make_buffer();
    ocean::buffer_data(m.vertices, GLsizeiptr(data.size() * sizeof(glm::vec3)), data.data(), GL_STATIC_DRAW);
    m.vao = ocean::make_vertex_array();
    for (GLuint a = 0; a < 2; ++a)  // (position, normal) pairs: attribute a at a vec3 into each
        ocean::vertex_attribute(m.vao, a, m.vertices, 3, 2 * sizeof(glm::vec3), GLintptr(a * sizeof(glm::vec3)));
    m.count = int(data.size() / 2);
    return m;
}

BodyMeshes::BodyMeshes() {
    std::vector<glm::vec3> cube;  // (position, normal) pairs, two triangles a face
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 0.5f;
            v[(axis + 2) % 3] = 0.5f * sign;  // counter-clockwise seen from outside
            const glm::vec3 c = 0.5f * n;
            const glm::vec3 corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
            for (int i : {0, 1, 2, 0, 2, 3}) cube.insert(cube.end(), {corners[i], n});
        }
    cube_ = upload(cube);
    std::vector<glm::vec3> sphere;
    const int rings = 16, segments = 32;
    const auto point = [&](int ring, int segment) {
        const double theta = ocean::kPi * ring / rings, phi = ocean::kTwoPi * segment / segments;
        return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const glm::vec3 a = point(r, s), b = point(r + 1, s), c = point(r + 1, s + 1), d = point(r, s + 1);
            for (const glm::vec3& p : {a, c, b, a, d, c}) sphere.insert(sphere.end(), {0.5f * p, p});
        }
    sphere_ = upload(sphere);
    hull_ = upload(hull_triangles());
}

// Triangles (position, normal) of the unit hull: the two sides lofted between sections and the
// deck, each flat-shaded, counter-clockwise from outside. The sides meet at the bow and the stern
// (hull_half_beam is 0 at both ends), so no end face is needed.
std::vector<glm::vec3> BodyMeshes::hull_triangles() {
    const int sections = 32, levels = 8;
    const auto side_point = [](int i, int j, float sign) {
        const double x = -0.5 + double(i) / sections, y = -0.5 + double(j) / levels;
        return glm::vec3(float(x), float(y), sign * float(hull_half_beam(x, y)));
    };
    std::vector<glm::vec3> out;
    const auto triangle = [&out](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 outward) {
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-9f) return;  // at the bow's and the stern's edges, where the sides meet
        n = glm::normalize(n);
        if (glm::dot(n, outward) < 0) std::swap(b, c), n = -n;
        out.insert(out.end(), {a, n, b, n, c, n});
    };
    for (float sign : {-1.0f, 1.0f})
        for (int i = 0; i < sections; ++i)
            for (int j = 0; j < levels; ++j) {
                const glm::vec3 a = side_point(i, j, sign), b = side_point(i + 1, j, sign),
                                c = side_point(i + 1, j + 1, sign), d = side_point(i, j + 1, sign);
                const glm::vec3 outward(0.0f, -0.3f, sign);  // out of the side, and down near the keel
                triangle(a, b, c, outward);
                triangle(a, c, d, outward);
            }
    for (int i = 0; i < sections; ++i) {  // the deck, y = 0.5
        const glm::vec3 a = side_point(i, levels, -1), b = side_point(i + 1, levels, -1),
                        c = side_point(i + 1, levels, 1), d = side_point(i, levels, 1);
        triangle(a, b, c, {0, 1, 0});
        triangle(a, c, d, {0, 1, 0});
    }
    return out;
}

void BodyMeshes::draw(ShapeKind kind) const {
    const Mesh& m = kind == ShapeKind::Sphere ? sphere_ : kind == ShapeKind::Hull ? hull_ : cube_;
    glBindVertexArray(m.vao.id());
    glDrawArrays(GL_TRIANGLES, 0, m.count);
}

}  // namespace step07
