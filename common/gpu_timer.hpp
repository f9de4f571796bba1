// GPU time per render pass, from GL timer queries, for --bench. Queries are read a few frames
// late (when the GPU has finished) so timing never stalls the pipeline.
#pragma once

#include "common/gl.hpp"

#include <deque>
#include <map>
#include <string>
#include <vector>

namespace ocean {

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
        double median_ms = 0, mean_ms = 0, min_ms = 0;
    };
    // In the order the passes first ran.
    std::vector<PassStats> stats();
    // The table --bench prints.
    std::string report(double wall_seconds, int frames);

private:
    struct Pending { std::string pass; Query query; };
    bool enabled_ = false;
    std::string open_pass_;
    Query open_query_;
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
