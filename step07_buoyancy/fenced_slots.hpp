// The bookkeeping both read-backs share (map_readback.hpp, gpu_queries.hpp): two slots, each a
// copy queued on the GPU with a fence after it. A copy goes into a free slot; the oldest in flight
// is handed back a frame later. Its owner asks for it before queuing the frame's own copy, and
// waits for it: a copy queued a whole frame ago has long landed on a GPU that keeps up (the wait
// costs nothing there), and the latency is then exactly one frame, so runs on a fixed clock are
// the same run after run (llvmpipe, busy, may take longer).
#pragma once

#include "common/gl.hpp"

#include <array>
#include <optional>

namespace step07 {

class FencedSlots {
public:
    static constexpr int kSlots = 2;
    FencedSlots() = default;
    ~FencedSlots() {
        for (GLsync f : fences_)
            if (f != nullptr) glDeleteSync(f);
    }
    FencedSlots(const FencedSlots&) = delete;
    FencedSlots& operator=(const FencedSlots&) = delete;

    // A slot with nothing in flight, if any.
    std::optional<int> free_slot() const {
        for (int s = 0; s < kSlots; ++s)
            if (fences_[std::size_t(s)] == nullptr) return s;
        return std::nullopt;
    }
    // After queuing slot s's copy: the fence that says when it is done.
    void sent(int s) {
        fences_[std::size_t(s)] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        order_[std::size_t(s)] = sent_++;
    }
    // The oldest slot in flight, once its copy has landed (waited for: see above); its fence is
    // deleted. Nothing when no copy is in flight.
    std::optional<int> landed() {
        int oldest = -1;
        for (int s = 0; s < kSlots; ++s)
            if (fences_[std::size_t(s)] != nullptr && (oldest < 0 || order_[std::size_t(s)] < order_[std::size_t(oldest)])) oldest = s;
        if (oldest < 0) return std::nullopt;
        // GL_SYNC_FLUSH_COMMANDS_BIT makes sure the fence reaches the GPU; 10 s: a GPU that lost
        // the copy rather than one that is slow. A web page may not block (WebGL's longest client
        // wait is 0), and its fences move only when the browser has had its turn, between two
        // frames: a copy queued a frame ago has then usually landed, and if not, WebGL's read-back
        // waits for it, so the data is the same and so is the one frame.
#if defined(__EMSCRIPTEN__)
        GLenum state = glClientWaitSync(fences_[std::size_t(oldest)], 0, 0);
        if (state == GL_TIMEOUT_EXPIRED) state = GL_CONDITION_SATISFIED;
#else
        const GLenum state = glClientWaitSync(fences_[std::size_t(oldest)], GL_SYNC_FLUSH_COMMANDS_BIT, 10000000000ull);
#endif
        glDeleteSync(fences_[std::size_t(oldest)]);
        fences_[std::size_t(oldest)] = nullptr;
        if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return std::nullopt;
        return oldest;
    }
    // Drops every copy in flight (their results would be stale: the maps came from elsewhere).
    void forget() {
        for (GLsync& f : fences_)
            if (f != nullptr) glDeleteSync(f), f = nullptr;
    }

private:
    std::array<GLsync, kSlots> fences_{};
    std::array<long, kSlots> order_{};
    long sent_ = 0;
};

}  // namespace step07
