#include "step07_buoyancy/gpu_queries.hpp"

#include <cstring>

namespace step07 {

void GpuQueries::submit(const std::vector<glm::vec2>& points, const step05::OceanSimulation& ocean,
                        const step06::CascadeView& view, double time, int steps) {
    if (points.empty()) return;
    const std::optional<int> slot = slots_.free_slot();
    if (!slot) return;
    Batch* free = &batches_[std::size_t(*slot)];
    ocean::ShaderProgram* p = programs_("height_query", {"step07_buoyancy/shaders/height_query.comp"}, {});
    if (p == nullptr) return;
    if (free->capacity < points.size()) {
        free->points = ocean::make_buffer();
        free->answers = ocean::make_buffer();
        free->readback = ocean::make_buffer();
        glNamedBufferStorage(free->points.id(), GLsizeiptr(points.size() * sizeof(glm::vec2)), nullptr, GL_DYNAMIC_STORAGE_BIT);
        glNamedBufferStorage(free->answers.id(), GLsizeiptr(points.size() * sizeof(GpuAnswer)), nullptr, 0);
        glNamedBufferStorage(free->readback.id(), GLsizeiptr(points.size() * sizeof(GpuAnswer)), nullptr, GL_MAP_READ_BIT);
        free->capacity = points.size();
    }
    glNamedBufferSubData(free->points.id(), 0, GLsizeiptr(points.size() * sizeof(glm::vec2)), points.data());
    view.upload(*p);
    ocean.bind_maps(*p);
    p->set("u_count", int(points.size()));
    p->set("u_steps", steps);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, free->points.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, free->answers.id());
    glUseProgram(p->id());
    glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
    // The copy into the mappable buffer reads what the dispatch wrote.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(free->answers.id(), free->readback.id(), 0, 0, GLsizeiptr(points.size() * sizeof(GpuAnswer)));
    slots_.sent(*slot);
    free->batch.time = time;
    free->batch.origin = view.origin;
    free->batch.points = points;
}

std::optional<GpuAnswers> GpuQueries::take() {
    const std::optional<int> slot = slots_.landed();
    if (!slot) return std::nullopt;
    Batch* oldest = &batches_[std::size_t(*slot)];
    GpuAnswers out = std::move(oldest->batch);
    out.answers.resize(out.points.size());
    const std::size_t bytes = out.answers.size() * sizeof(GpuAnswer);
    const void* data = glMapNamedBufferRange(oldest->readback.id(), 0, GLsizeiptr(bytes), GL_MAP_READ_BIT);
    if (data == nullptr) return std::nullopt;
    std::memcpy(out.answers.data(), data, bytes);
    glUnmapNamedBuffer(oldest->readback.id());
    return out;
}

}  // namespace step07
