// The run loop's collaborators (App::run_loop in app.cpp strings them together): the frame
// clock, closing on Ctrl-C, capturing and writing the last frame, the --export folder, the
// hooks only the tests use, and the machine-readable --bench line.
#pragma once

#include "common/cli.hpp"
#include "common/context.hpp"
#include "common/gpu_timer.hpp"
#include "common/image.hpp"

#include <glm/vec2.hpp>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace ocean {

// Simulation time and frame time. With --time or --dt the clock is fixed (deterministic runs):
// every frame advances it by --dt (0 without). Otherwise it follows the wall clock, from --start-at.
class FrameClock {
public:
    explicit FrameClock(const Options& options);
    double start_time() const { return start_time_; }
    struct Tick {
        double dt;       // what the simulation advances (0 when paused)
        double real_dt;  // wall seconds since the previous frame (camera speed, the panel)
        double wall;     // wall seconds since the start
    };
    // `warming_up`: the step is not in its steady state yet (App::offer_warm_up).
    Tick tick(int frame, bool paused, bool warming_up = false);
    // What --bench times: the steady state, from the first frame after frame 0 (which pays for
    // compilation and uploads) that the step no longer spends warming up (auto's backend trial,
    // which runs the slower backend on half of its frames), to now. A run that never leaves its
    // warm-up is timed from frame 1.
    double bench_seconds() const;
    int bench_first_frame() const { return bench_started_ ? bench_first_frame_ : 1; }
    // Ends the clock before `frame` (after the caller's glFinish), where --bench starts timing the
    // passes one by one: a glFinish around each serialises the CPU and llvmpipe's threads, so the
    // frames per second come from the frames before, drawn as a user sees them. Ignored unless
    // the clock has started before `frame` (then it times to the end, as without a stop).
    void stop(int frame);
    // How many of a run's `frames` the clock timed.
    int bench_frames(int frames) const { return (stopped() ? stop_frame_ : frames) - bench_first_frame(); }
    bool stopped() const { return stop_frame_ > 0; }  // a stop is always after frame 1

private:
    using Clock = std::chrono::steady_clock;
    bool fixed_;
    double fixed_dt_, start_time_;
    Clock::time_point start_ = Clock::now(), previous_ = start_, frame_one_ = start_, bench_start_ = start_;
    bool bench_started_ = false;
    int bench_first_frame_ = 1, stop_frame_ = 0;  // stop_frame_: 0 until stop() takes
    Clock::time_point stop_ = start_;
};

// Ctrl-C (SIGINT) and SIGTERM close the step like its window's close button while this object
// lives: the frame ends, the GL objects are released, the exit status is 0.
class CloseOnSignal {
public:
    CloseOnSignal();
    ~CloseOnSignal();
    CloseOnSignal(const CloseOnSignal&) = delete;
    CloseOnSignal& operator=(const CloseOnSignal&) = delete;
    bool requested() const;
};

// The picture in the context's target (nothing while minimised).
Image capture_frame(const Context& context, glm::ivec2 size);
// Writes a screenshot (creating its folder); returns its absolute path. Throws ocean::Error.
std::string save_screenshot(const Image& image, const std::string& path);
// Creates the --export folder; returns it. Throws ocean::Error.
std::string prepare_export_dir(const std::string& dir);

// The hooks only the tests use, kept out of the run loop's own logic: --simulate-minimise (frames
// 2 and 3 get a 0x0 framebuffer, as a minimised window reports, and a real window is iconified and
// restored) and --resource-log N (resident memory and live GL objects every N frames, the soak).
class TestProbes {
public:
    explicit TestProbes(const Options& options)
        : minimise_(options.simulate_minimise), resource_log_(options.resource_log) {}
    // The framebuffer size frame `frame` should use.
    glm::ivec2 framebuffer_size(Context& context, int frame, glm::ivec2 size) const;
    // After frame `frame` was presented.
    void after_frame(int frame) const;

private:
    bool minimise_;
    int resource_log_;
};

// The --bench results as one CSV row, the format ./ocean bench collects (said here only):
//   bench-csv-header: step,size,fps,total_ms,passes,<extra labels>
//   bench-csv: <step>,<WxH>,<fps>,<sum of the passes' wall ms>,<pass=ms;...>,<extra ms...>
// (an extra figure that is not a finite number, not measured, is left empty)
std::string bench_csv_line(const std::string& step, glm::ivec2 size, GpuTimers& timers, double wall_seconds,
                           int frames, const std::vector<std::pair<std::string, double>>& extra);

}  // namespace ocean
