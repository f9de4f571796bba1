#include "common/gpu_timer.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace ocean {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// OpenGL ES 3.0 has no timer queries (WebGL 2 has them only as an extension that browsers often
// withhold): the ES build times the passes by the wall clock alone.
#if defined(OCEAN_GL_ES)
constexpr bool kTimerQueries = false;
#else
constexpr bool kTimerQueries = true;
#endif

void GpuTimers::begin(const std::string& pass) {
    if (!enabled_) return;
    open_pass_ = pass;
    open_ = true;
    glFinish();
    open_start_ = std::chrono::steady_clock::now();
#if !defined(OCEAN_GL_ES)
    if (spare_.empty()) spare_.push_back(make_query(GL_TIME_ELAPSED));
    open_query_ = std::move(spare_.back());
    spare_.pop_back();
    glBeginQuery(GL_TIME_ELAPSED, open_query_.id());
#endif
}

void GpuTimers::end() {
    if (!enabled_ || !open_) return;
    open_ = false;
#if !defined(OCEAN_GL_ES)
    glEndQuery(GL_TIME_ELAPSED);
    pending_.push_back({open_pass_, std::move(open_query_)});
#endif
    glFinish();
    wall_ms_[open_pass_].push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - open_start_).count());
    if (std::find(order_.begin(), order_.end(), open_pass_) == order_.end()) order_.push_back(open_pass_);
}

void GpuTimers::collect(bool wait) {
#if !defined(OCEAN_GL_ES)
    while (!pending_.empty()) {
        Pending& front = pending_.front();
        GLint available = GL_FALSE;
        if (!wait) glGetQueryObjectiv(front.query.id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!wait && available != GL_TRUE) break;
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(front.query.id(), GL_QUERY_RESULT, &nanoseconds);
        samples_ms_[front.pass].push_back(double(nanoseconds) * 1e-6);
        spare_.push_back(std::move(front.query));
        pending_.pop_front();
    }
#else
    (void)wait;
#endif
}

std::vector<GpuTimers::PassStats> GpuTimers::stats() {
    collect(true);
    std::vector<PassStats> out;
    for (const auto& name : order_) {
        std::vector<double> v = kTimerQueries ? samples_ms_[name] : wall_ms_[name];
        if (v.empty()) continue;
        std::sort(v.begin(), v.end());
        PassStats s;
        s.name = name;
        s.samples = int(v.size());
        s.median_ms = kTimerQueries ? median(v) : 0;
        s.min_ms = kTimerQueries ? v.front() : 0;
        s.median_wall_ms = median(wall_ms_[name]);
        out.push_back(s);
    }
    return out;
}

std::string GpuTimers::report(double wall_seconds, int frames, int warm_up_frames) {
    std::ostringstream out;
    char line[160];
    // Medians, not means: one stalled frame (a shader compile, a swap) would dominate a mean.
    out << "bench: pass             GPU median ms  GPU min ms  wall median ms  samples\n";
    if (!kTimerQueries) out << "bench: (OpenGL ES 3.0 has no timer queries: the GPU columns are 0, the wall clock is the figure)\n";
    double total = 0, total_wall = 0;
    for (const auto& s : stats()) {
        std::snprintf(line, sizeof line, "bench: %-16s %13.3f %11.3f %15.3f  %7d\n", s.name.c_str(),
                      s.median_ms, s.min_ms, s.median_wall_ms, s.samples);
        out << line;
        total += s.median_ms;
        total_wall += s.median_wall_ms;
    }
    std::snprintf(line, sizeof line, "bench: %-16s %13.3f %11s %15.3f\n", "all passes", total, "", total_wall);
    out << line;
    const double fps = wall_seconds > 0 ? frames / wall_seconds : 0;
    std::snprintf(line, sizeof line,
                  "bench: %d frames after %d warm-up frames in %.3f s: %.1f frames per second (wall clock)\n", frames,
                  warm_up_frames, wall_seconds, fps);
    out << line;
    return out.str();
}

}  // namespace ocean
