#include "step07_buoyancy/map_readback.hpp"

#include <cstring>

namespace step07 {

void MapReadback::request(const step05::OceanSimulation& ocean, double time) {
    const std::optional<int> slot = slots_.free_slot();
    if (!slot) return;
    Copy* free = &copies_[std::size_t(*slot)];
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
    slots_.sent(*slot);
    free->time = time;
    free->n = n;
}

std::optional<ArrivedMaps> MapReadback::take() {
    const std::optional<int> slot = slots_.landed();
    if (!slot) return std::nullopt;
    const Copy* oldest = &copies_[std::size_t(*slot)];
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
