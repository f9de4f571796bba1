// Chapter 7.5: the GPU's maps back on the CPU without stalling. Reading a texture into client
// memory (glGetTextureImage, glReadPixels) waits until the GPU has finished everything queued
// before it (the frame's transforms): the CPU then idles for the GPU's whole frame. Into a pixel buffer object it only queues a copy;
// a fence after it says when the copy is done, and the buffer is mapped then, a frame later.
// So the queries see the sea of the previous frame: at 60 frames a second the surface has moved
// by its vertical speed times 1/60 s, a few centimetres (the tests measure it).
#pragma once

#include "common/gl.hpp"
#include "step06_foam_sky/sea.hpp"
#include "step07_buoyancy/fenced_slots.hpp"

#include <array>
#include <optional>
#include <vector>

namespace step07 {

struct ArrivedMaps {
    double time = 0;  // the simulation time the maps belong to
    int n = 0;
    std::vector<float> displacement, slopes;  // level 0, layer major, RGBA
};

class MapReadback {
public:
    // Queues the copy of both maps' level 0 (every cascade) made for `time`; returns at once.
    // With both buffers still in flight the request is dropped.
    void request(const step06::SeaSimulation& ocean, double time);
    // The oldest copy in flight (an earlier frame's: call it before request), waited for if it has
    // not landed yet (fenced_slots.hpp says why that costs nothing on a GPU).
    std::optional<ArrivedMaps> take();
    // The maps of this frame at once, waiting for the GPU: for the first sea, when nothing moves yet.
    static ArrivedMaps read_now(const step06::SeaSimulation& ocean, double time);
    // Drops the copies in flight (this frame's maps came from the CPU).
    void forget() { slots_.forget(); }

private:
    struct Copy {
        ocean::Buffer buffer;
        std::size_t bytes = 0;
        double time = 0;
        int n = 0;
    };
    std::array<Copy, FencedSlots::kSlots> copies_;
    FencedSlots slots_;
};

}  // namespace step07
