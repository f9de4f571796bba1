// Height queries answered on the GPU (shaders/height_query.comp), for the many small things that
// only need a height: particles, floating debris, a camera that must stay above the waves. The
// points go up, one dispatch answers them all from the maps already on the GPU, and only the
// answers come back (16 bytes each), through a buffer and a fence as map_readback does: exactly a
// frame late (fenced_slots.hpp).
#pragma once

#include "common/gl.hpp"
#include "step07_buoyancy/fenced_slots.hpp"
#include "common/shader.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <vector>

namespace step07 {

struct GpuAnswer {
    float height;
    float normal_x, normal_z;  // the unit normal's horizontal components (y = sqrt(1 - x^2 - z^2))
    float miss;                // metres between p and where the answer's rest point is drawn
};

struct GpuAnswers {
    double time = 0;
    glm::dvec2 origin{0.0};  // the world origin the points were given from
    std::vector<glm::vec2> points;
    std::vector<GpuAnswer> answers;
};

class GpuQueries {
public:
    explicit GpuQueries(ocean::ProgramFactory programs) : programs_(std::move(programs)) {}

    // Queues the answers for `points` (metres from view.origin) on the maps of `ocean` at `time`,
    // `steps` Newton steps each. Dropped when both buffers are still in flight.
    void submit(const std::vector<glm::vec2>& points, const step05::OceanSimulation& ocean,
                const step06::CascadeView& view, double time, int steps = 4);
    // The oldest batch in flight (an earlier frame's: call it before submit), waited for if it is
    // not answered yet (fenced_slots.hpp says why that costs nothing on a GPU).
    std::optional<GpuAnswers> take();

private:
    struct Batch {
        ocean::Buffer points, answers, readback;
        std::size_t capacity = 0;
        GpuAnswers batch;
    };
    ocean::ProgramFactory programs_;
    std::array<Batch, FencedSlots::kSlots> batches_;
    FencedSlots slots_;
};

}  // namespace step07
