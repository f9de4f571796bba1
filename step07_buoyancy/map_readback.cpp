#include "step07_buoyancy/map_readback.hpp"

#include <cstring>

namespace step07 {

MapReadback::~MapReadback() {
    for (Slot& s : slots_)
        if (s.fence != nullptr) glDeleteSync(s.fence);
}

int MapReadback::frames_in_flight() const {
    int n = 0;
    for (const Slot& s : slots_) n += s.fence != nullptr ? 1 : 0;
    return n;
}

void MapReadback::request(const step05::OceanSimulation& ocean, double time) {
    Slot* free = nullptr;
    for (Slot& s : slots_)
        if (s.fence == nullptr) free = &s;
    if (free == nullptr) return;
    const int n = ocean.resolution();
    const std::size_t map_bytes = std::size_t(n) * std::size_t(n) * std::size_t(ocean.cascade_count()) * 4 * sizeof(float);
    if (free->bytes != 2 * map_bytes) {
        free->buffer = ocean::make_buffer();
        glNamedBufferStorage(free->buffer.id(), GLsizeiptr(2 * map_bytes), nullptr, GL_MAP_READ_BIT);
        free->bytes = 2 * map_bytes;
    }
    // With a buffer bound to GL_PIXEL_PACK_BUFFER the "pointer" is an offset into it: the copy is
    // queued, not waited for.
    glBindBuffer(GL_PIXEL_PACK_BUFFER, free->buffer.id());
    glGetTextureImage(ocean.displacement_texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(map_bytes), nullptr);
    glGetTextureImage(ocean.slopes_texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(map_bytes),
                      reinterpret_cast<void*>(map_bytes));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    free->fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    free->time = time;
    free->n = n;
    free->order = requests_++;
}

std::optional<ArrivedMaps> MapReadback::take() {
    Slot* oldest = nullptr;
    for (Slot& s : slots_)
        if (s.fence != nullptr && (oldest == nullptr || s.order < oldest->order)) oldest = &s;
    if (oldest == nullptr) return std::nullopt;
    // Timeout 0: only asks. GL_SYNC_FLUSH_COMMANDS_BIT makes sure the fence reaches the GPU.
    const GLenum state = glClientWaitSync(oldest->fence, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return std::nullopt;
    glDeleteSync(oldest->fence);
    oldest->fence = nullptr;
    ArrivedMaps out;
    out.time = oldest->time;
    out.n = oldest->n;
    const std::size_t half = oldest->bytes / 2;
    out.displacement.resize(half / sizeof(float));
    out.slopes.resize(half / sizeof(float));
    const auto* data = static_cast<const char*>(glMapNamedBufferRange(oldest->buffer.id(), 0, GLsizeiptr(oldest->bytes), GL_MAP_READ_BIT));
    if (data == nullptr) return std::nullopt;
    std::memcpy(out.displacement.data(), data, half);
    std::memcpy(out.slopes.data(), data + half, half);
    glUnmapNamedBuffer(oldest->buffer.id());
    return out;
}

}  // namespace step07
