#include "step07_buoyancy/body_painter.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace step07 {

void BodyPainter::draw(const std::vector<FloatingBody>& bodies, glm::dvec3 world_origin,
                       const glm::mat4& view_projection, glm::dvec3 eye, const step06::Sky& sky,
                       const step06::LookParams& look) {
    if (!programs_ || bodies.empty()) return;
    ocean::ShaderProgram* p =
        programs_("body", {"step07_buoyancy/shaders/body.vert", "step07_buoyancy/shaders/body.frag"}, {});
    if (p == nullptr) return;
    if (!meshes_) meshes_ = std::make_unique<BodyMeshes>();
    look.upload_shading(*p);
    p->set("u_view_projection", view_projection);
    p->set("u_eye", glm::vec3(eye - world_origin));
    p->set("u_sky_max_lod", sky.max_lod());
    sky.bind();
    glUseProgram(p->id());
    glEnable(GL_DEPTH_TEST);
    const glm::vec3 colours[3] = {{0.8f, 0.12f, 0.03f}, {0.35f, 0.22f, 0.12f}, {0.75f, 0.75f, 0.72f}};
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const FloatingBody& body = bodies[b];
        const Shape& shape = body.settings().shape;
        const glm::vec3 scale = shape.kind == ShapeKind::Sphere ? glm::vec3(float(shape.size.x)) : glm::vec3(shape.size);  // box and hull: (length, depth, beam)
        // From the world origin near the camera, in double, then float: small numbers anywhere.
        const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(body.position() - world_origin)) *
                                glm::mat4_cast(glm::quat(body.orientation())) *
                                glm::translate(glm::mat4(1.0f), glm::vec3(body.shape_centre())) *
                                glm::scale(glm::mat4(1.0f), scale);
        p->set("u_model", model);
        p->set("u_scale", scale);
        p->set("u_colour", colours[b % 3]);
        meshes_->draw(shape.kind);
    }
    glDisable(GL_DEPTH_TEST);
}

}  // namespace step07
