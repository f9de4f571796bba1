// Chapter 7.5, as a program runs it: each frame, the sea the bodies read. The maps the renderer
// draws reach the CPU from the FFTW backend directly (this frame's), or from the GPU through
// map_readback.hpp (a frame late); the feed keeps the last two, so the bodies see the sea move
// from one to the other over the frame. A part of its own, so that any program with bodies on
// the sea uses it as step07's does.
#pragma once

#include "step06_foam_sky/sea.hpp"
#include "step07_buoyancy/map_readback.hpp"
#include "step07_buoyancy/sea_surface.hpp"

#include <optional>

namespace step07 {

class SeaFeed {
public:
    // Takes the newest sea of `sea` at `time` (this frame's or the latest read back); whether one
    // arrived. The very first sea is read at once, waiting for the GPU: with no bodies yet there
    // is nothing to keep moving meanwhile, and they are dropped on the sea of the frame they
    // appear in. After it, last frame's copy first (a frame late), then this frame's is queued.
    bool update(const step06::Sea& sea, double time);
    bool ready() const { return now_.has_value(); }
    // The sea at the frame's start and end (ready() only). The sea moved from one to the other over
    // this frame only if a new one came: a frame with none (the read-back still in flight) holds
    // the latest (still water for the drag) rather than replaying the last frame's motion.
    const MapSea& before() const { return arrived_ ? before_->sea : now_->sea; }
    const MapSea& now() const { return now_->sea; }
    double interval() const { return now_->time - before_->time; }  // seconds between the last two seas
    int latency_frames() const { return latency_frames_; }          // 0: this frame's (FFTW); 1: read back

private:
    struct TimedSea {
        MapSea sea;
        double time = 0;
    };
    std::optional<TimedSea> newest(const step06::Sea& sea, double time);

    std::optional<TimedSea> before_, now_;
    bool arrived_ = false;
    MapReadback readback_;
    int latency_frames_ = 0;
};

}  // namespace step07
