// Time per render pass for --bench, measured two ways:
//  - GPU time from GL timer queries (GL_TIME_ELAPSED), read a few frames late so reading never
//    stalls: the figure to quote on a real GPU (not in the ES build: ES 3.0 has no timer queries);
//  - wall time from a glFinish() before and after the pass: the figure to quote on llvmpipe,
//    which defers its work to the next flush and so gives timer queries little meaning.
// The glFinish calls serialise the CPU and the GPU (on llvmpipe, its threads: 3 to 5 % of step06's
// frame), so with a frame limit App times the passes only on the last quarter of the frames and
// reads the frames per second before them (FrameClock::stop).
#pragma once

#include "common/gl.hpp"

#include <chrono>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace ocean {

// The median of some timings (the mean of the middle two for an even count, 0 for none): what every
// benchmark here quotes, since one stalled frame (a shader compile, a swap) would dominate a mean.
double median(std::vector<double> values);

// The wall milliseconds `work` takes with the GL queue drained before and after it (glFinish):
// what a pass costs on llvmpipe, where timer queries say little, and what a choice between two
// ways of drawing (FasterOfTwo) records.
template <class Work>
double wall_ms_around_finish(Work&& work) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

class GpuTimers {
public:
    void set_enabled(bool enabled) { enabled_ = enabled; }
    bool enabled() const { return enabled_; }

    // Brackets one pass; passes must not nest (GL allows one GL_TIME_ELAPSED query at a time).
    void begin(const std::string& pass);
    void end();
    // Collects the results that are ready; call once a frame.
    void collect(bool wait = false);

    struct PassStats {
        std::string name;
        int samples = 0;
        double median_ms = 0, min_ms = 0;  // GPU (timer query)
        double median_wall_ms = 0;                     // CPU wall clock around glFinish
    };
    // In the order the passes first ran.
    std::vector<PassStats> stats();
    // The table --bench prints; `frames` were timed in `wall_seconds`, after `warm_up_frames`.
    std::string report(double wall_seconds, int frames, int warm_up_frames);

private:
    struct Pending { std::string pass; Query query; };
    bool enabled_ = false;
    std::string open_pass_;
    bool open_ = false;  // between begin and end
    Query open_query_;
    std::chrono::steady_clock::time_point open_start_;
    std::map<std::string, std::vector<double>> wall_ms_;
    std::deque<Pending> pending_;
    std::vector<Query> spare_;
    std::vector<std::string> order_;
    std::map<std::string, std::vector<double>> samples_ms_;
};

// Times one pass for the lifetime of the object: `auto t = GpuScope(timers, "ocean");`.
class GpuScope {
public:
    GpuScope(GpuTimers& timers, const std::string& pass) : timers_(timers) { timers_.begin(pass); }
    ~GpuScope() { timers_.end(); }
    GpuScope(const GpuScope&) = delete;
    GpuScope& operator=(const GpuScope&) = delete;

private:
    GpuTimers& timers_;
};

}  // namespace ocean
