#include "step07_buoyancy/query_grid.hpp"

#include "step07_buoyancy/sea_query.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>

namespace step07 {

void QueryGrid::declare(ocean::ParamRegistry& p) {
    const auto group = p.group("queries");
    p.add_int("queries", &count_, 0, 100000,
              "height queries a frame on a grid ahead of the camera, drawn as dots where the water is");
#ifndef OCEAN_GL_PORTABLE  // a compute shader answers them on the GPU: GL 4.5 only
    p.add_choice("query_device", &device_, {"cpu", "gpu"},
                 "where the queries are answered: cpu (sea_query.cpp, every core, this frame's maps) or gpu "
                 "(height_query.comp, answers a frame late)");
#endif
}

void QueryGrid::update(const MapSea& maps, const step06::Sea& sea, glm::dvec3 eye, glm::vec3 forward, double time) {
    if (count_ == 0) {
        dots_.clear();
        return;
    }
    const glm::dvec2 ahead = glm::normalize(glm::dvec2(forward.x, forward.z) + glm::dvec2(1e-9, 0)), side(-ahead.y, ahead.x);
    const int columns = int(std::ceil(std::sqrt(double(count_))));
    std::vector<glm::dvec2> world;
    for (int i = 0; i < count_; ++i)
        world.push_back(glm::dvec2(eye.x, eye.z) + (5.0 + 0.7 * (i / columns)) * ahead + 0.7 * (i % columns - columns / 2) * side);
    if (device_ == 0) {
        const std::vector<SeaPoint> answers = query_many(maps, world);
        dots_.resize(world.size());
        for (std::size_t i = 0; i < world.size(); ++i) dots_[i] = {world[i].x, answers[i].height, world[i].y};
        return;
    }
#ifndef OCEAN_GL_PORTABLE
    // On the GPU: this frame's points go up; last frame's answers come back.
    if (!gpu_) gpu_ = std::make_unique<GpuQueries>(programs_);
    std::vector<glm::vec2> relative;
    for (const auto& w : world) relative.emplace_back(w - sea.cascades().origin);
    std::optional<GpuAnswers> arrived = gpu_->take();  // last frame's, then this frame's
    gpu_->submit(relative, sea.simulation(), sea.cascades(), time);
    if (arrived) {
        dots_.resize(arrived->points.size());
        for (std::size_t i = 0; i < arrived->points.size(); ++i) {
            const glm::dvec2 w = arrived->origin + glm::dvec2(arrived->points[i]);
            dots_[i] = {w.x, arrived->answers[i].height, w.y};
        }
    }
#else
    (void)sea;  // read by the GPU's answers, which need compute shaders
    (void)time;
#endif
}

void QueryGrid::draw(glm::dvec3 origin, const glm::mat4& view_projection) {
    const std::vector<glm::dvec3>& dots = dots_;
    if (dots.empty()) return;
    ocean::ShaderProgram* p = programs_("query_points", {"step07_buoyancy/shaders/query_points.vert",
                                                         "step07_buoyancy/shaders/query_points.frag"}, {});
    if (p == nullptr) return;
    std::vector<glm::vec3> positions;
    for (const auto& d : dots) positions.emplace_back(d - origin);  // small floats anywhere on the ocean
    if (vao_.id() == 0) {
        buffer_ = ocean::make_buffer();
        vao_ = ocean::make_vertex_array();
        ocean::vertex_attribute(vao_, 0, buffer_, 3, sizeof(glm::vec3));
    }
    ocean::buffer_data(buffer_, GLsizeiptr(positions.size() * sizeof(glm::vec3)), positions.data(), GL_STREAM_DRAW);
    p->set("u_view_projection", view_projection);
    glUseProgram(p->id());
#ifndef OCEAN_GL_ES  // ES always takes a point's size from gl_PointSize
    glEnable(GL_PROGRAM_POINT_SIZE);
#endif
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_POINTS, 0, GLsizei(positions.size()));
    glDisable(GL_DEPTH_TEST);
#ifndef OCEAN_GL_ES
    glDisable(GL_PROGRAM_POINT_SIZE);
#endif
}

}  // namespace step07
