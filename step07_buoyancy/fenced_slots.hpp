// The bookkeeping both read-backs share (map_readback.hpp, gpu_queries.hpp): two slots, each a
// copy queued on the GPU with a fence after it. A copy goes into a free slot; the oldest slot whose
// fence has signalled is handed back, without ever waiting; with both in flight the GPU is two
// frames behind and the next copy is dropped.
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
    // The oldest slot whose copy has landed (its fence then deleted); nothing if it has not yet.
    std::optional<int> landed() {
        int oldest = -1;
        for (int s = 0; s < kSlots; ++s)
            if (fences_[std::size_t(s)] != nullptr && (oldest < 0 || order_[std::size_t(s)] < order_[std::size_t(oldest)])) oldest = s;
        if (oldest < 0) return std::nullopt;
        // Timeout 0: only asks. GL_SYNC_FLUSH_COMMANDS_BIT makes sure the fence reaches the GPU.
        const GLenum state = glClientWaitSync(fences_[std::size_t(oldest)], GL_SYNC_FLUSH_COMMANDS_BIT, 0);
        if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return std::nullopt;
        glDeleteSync(fences_[std::size_t(oldest)]);
        fences_[std::size_t(oldest)] = nullptr;
        return oldest;
    }
    int in_flight() const {
        int n = 0;
        for (GLsync f : fences_) n += f != nullptr ? 1 : 0;
        return n;
    }

private:
    std::array<GLsync, kSlots> fences_{};
    std::array<long, kSlots> order_{};
    long sent_ = 0;
};

}  // namespace step07
