#include "step07_buoyancy/map_readback.hpp"

#include "common/gl_texture.hpp"

#include <cstddef>
#include <utility>

namespace step07 {

void MapReadback::request(const step06::SeaSimulation& ocean, double time) {
    const std::optional<int> slot = slots_.free_slot();
    if (!slot) return;
    Copy* free = &copies_[std::size_t(*slot)];
    const int n = ocean.resolution();
    const std::size_t map_bytes = std::size_t(n) * std::size_t(n) * std::size_t(ocean.cascade_count()) * 4 * sizeof(float);
    const bool resized = free->bytes != 2 * map_bytes;
    if (resized) {
        free->buffer = ocean::make_buffer();
        free->bytes = 2 * map_bytes;
    }
    // New storage for every copy in a browser. Chromium keeps a shadow of a read-usage buffer for
    // getBufferSubData, and once it has shadowed a buffer's storage it warns on the console at the
    // fence after every later write into it, even when the buffer was read in between ("READ-usage
    // buffer was written, then fenced, but written again before being read back": a frame a
    // warning, measured on chromium 156, and a learner's console shows nothing else). New storage
    // drops the shadow (tests/web/readback_quiet.sh). Natively the storage is kept.
#if defined(__EMSCRIPTEN__)
    const bool new_storage = true;
#else
    const bool new_storage = resized;
#endif
    if (new_storage) ocean::buffer_data(free->buffer, GLsizeiptr(free->bytes), nullptr, GL_STREAM_READ);  // the GPU writes, the CPU reads
    // Queued, not waited for: the copies land in the buffer when the GPU gets there.
    ocean::queue_layers_into_buffer(ocean.displacement_texture(), n, ocean.cascade_count(), free->buffer, 0);
    ocean::queue_layers_into_buffer(ocean.slopes_texture(), n, ocean.cascade_count(), free->buffer, GLintptr(map_bytes));
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
    // Both maps in one read, the displacement then the slopes.
    std::vector<float> both(oldest->bytes / sizeof(float));
    if (!ocean::read_buffer(oldest->buffer, GLsizeiptr(oldest->bytes), both.data())) return std::nullopt;
    const auto middle = both.begin() + std::ptrdiff_t(both.size() / 2);
    out.displacement.assign(both.begin(), middle);
    out.slopes.assign(middle, both.end());
    return out;
}

ArrivedMaps MapReadback::read_now(const step06::SeaSimulation& ocean, double time) {
    ArrivedMaps out;
    out.time = time;
    out.n = ocean.resolution();
    for (int layer = 0; layer < ocean.cascade_count(); ++layer) {
        for (const auto& [texture, map] : {std::pair{ocean.displacement_texture(), &out.displacement},
                                           std::pair{ocean.slopes_texture(), &out.slopes}}) {
            const std::vector<float> texels = ocean::read_texture_layer(texture, 0, layer, out.n);
            map->insert(map->end(), texels.begin(), texels.end());
        }
    }
    return out;
}

}  // namespace step07
