// The `queries` parameter: heights on a grid ahead of the camera, 0.7 m apart, what a game's
// particles or floating debris would ask of the sea. They are answered on the CPU (sea_query.cpp,
// every core, this frame's maps) or on the GPU (height_query.comp, a frame late: gpu_queries.hpp),
// and each answer is drawn as a dot where the water is (query_points.vert and .frag).
#pragma once

#include "common/gl.hpp"
#include "common/params.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/sea.hpp"
#ifndef OCEAN_GL_PORTABLE
#include "step07_buoyancy/gpu_queries.hpp"
#endif
#include "step07_buoyancy/sea_maps.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace step07 {

class QueryGrid {
public:
    void declare(ocean::ParamRegistry& p);
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }
    // This frame's grid in front of `eye` (world metres) along `forward`: on the CPU against
    // `maps` (what the bodies read), on the GPU against `sea`'s own maps.
    void update(const MapSea& maps, const step06::Sea& sea, glm::dvec3 eye, glm::vec3 forward, double time);
    // The latest answers as dots, from `origin` (the sea's world origin near the camera) with the
    // frame's view-projection, depth-tested against the sea.
    void draw(glm::dvec3 origin, const glm::mat4& view_projection);

private:
    ocean::ProgramFactory programs_;
    int count_ = 0, device_ = 0;  // the parameters queries and query_device (0: cpu)
#ifndef OCEAN_GL_PORTABLE
    std::unique_ptr<GpuQueries> gpu_;
#endif
    std::vector<glm::dvec3> dots_;  // world metres: the latest answers
    ocean::Buffer buffer_;
    ocean::VertexArray vao_;
};

}  // namespace step07
