#include "common/run_support.hpp"

#include "common/error.hpp"
#include "common/gl.hpp"
#include "common/platform.hpp"

#include <GLFW/glfw3.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

FrameClock::FrameClock(const Options& options)
    : fixed_(options.start_time.has_value() || options.fixed_dt.has_value()),
      fixed_dt_(options.fixed_dt.value_or(0.0)),
      start_time_(options.start_time.value_or(options.start_at.value_or(0.0))) {}

FrameClock::Tick FrameClock::tick(int frame, bool paused, bool warming_up) {
    const auto now = Clock::now();
    Tick t;
    t.real_dt = std::chrono::duration<double>(now - previous_).count();
    t.wall = std::chrono::duration<double>(now - start_).count();
    t.dt = paused ? 0.0 : (fixed_ ? fixed_dt_ : t.real_dt);
    previous_ = now;
    if (frame == 1) frame_one_ = now;
    if (frame >= 1 && !warming_up && !bench_started_) {
        bench_started_ = true;
        bench_start_ = now;
        bench_first_frame_ = frame;
    }
    return t;
}

double FrameClock::bench_seconds() const {
    return std::chrono::duration<double>((stopped() ? stop_ : Clock::now()) -
                                         (bench_started_ ? bench_start_ : frame_one_))
        .count();
}

void FrameClock::stop(int frame) {
    if (stopped() || !bench_started_ || frame <= bench_first_frame_) return;
    stop_ = Clock::now();
    stop_frame_ = frame;
}

namespace {
// A signal handler may only set a flag like this.
volatile std::sig_atomic_t g_close_requested = 0;
extern "C" void request_close_on_signal(int) { g_close_requested = 1; }
}  // namespace

CloseOnSignal::CloseOnSignal() {
    g_close_requested = 0;
    std::signal(SIGINT, request_close_on_signal);
    std::signal(SIGTERM, request_close_on_signal);
}

CloseOnSignal::~CloseOnSignal() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

bool CloseOnSignal::requested() const { return g_close_requested != 0; }

Image capture_frame(const Context& context, glm::ivec2 size) {
    if (size.x <= 0 || size.y <= 0) return {};
    return read_framebuffer(context.target_framebuffer(), size.x, size.y);
}

std::string save_screenshot(const Image& image, const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    if (auto error = save_png(image, path)) throw Error(*error);
    return fs::absolute(path).string();
}

std::string prepare_export_dir(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error("--export: cannot create '" + dir + "': " + ec.message());
    return dir;
}

glm::ivec2 TestProbes::framebuffer_size(Context& context, int frame, glm::ivec2 size) const {
    if (!minimise_ || (frame != 2 && frame != 3)) return size;
    if (GLFWwindow* window = context.window(); window != nullptr) {
        if (frame == 2) glfwIconifyWindow(window);
        if (frame == 3) glfwRestoreWindow(window);
    }
    return glm::ivec2(0);
}

void TestProbes::after_frame(int frame) const {
    if (resource_log_ > 0 && (frame + 1) % resource_log_ == 0)
        std::cout << "resources: frame " << frame + 1 << " rss_kb " << platform::resident_kilobytes().value_or(-1) << " gl_objects "
                  << live_gl_objects() << std::endl;
}

std::string bench_csv_line(const std::string& step, glm::ivec2 size, GpuTimers& timers, double wall_seconds,
                           int frames, const std::vector<std::pair<std::string, double>>& extra) {
    std::string header = "step,size,fps,total_ms,passes", row;
    double total = 0;
    std::string passes;
    char number[64];
    for (const auto& s : timers.stats()) {
        std::snprintf(number, sizeof number, "%.3f", s.median_wall_ms);
        passes += (passes.empty() ? "" : ";") + s.name + "=" + number;
        total += s.median_wall_ms;
    }
    std::snprintf(number, sizeof number, "%.2f,%.3f", wall_seconds > 0 ? frames / wall_seconds : 0.0, total);
    row = step + "," + std::to_string(size.x) + "x" + std::to_string(size.y) + "," + number + "," + passes;
    for (const auto& [label, ms] : extra) {
        header += "," + label;
        std::snprintf(number, sizeof number, "%.3f", ms);
        row += "," + (std::isfinite(ms) ? std::string(number) : std::string());  // not measured: empty
    }
    return "bench-csv-header: " + header + "\nbench-csv: " + row + "\n";
}

}  // namespace ocean
