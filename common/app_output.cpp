// App's output writing: --record's frames, the screenshot, --export, --bench, and the command that
// hands over to another step (Previous/Next).
#include "common/app.hpp"

#include "common/image.hpp"
#include "common/run_support.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

// --record: this frame as DIR/frame_NNNN.png (four digits, more past 9999), read before the
// buffers swap. The folder is created at the first frame. A frame that cannot be written throws
// (ocean::Error): a recording with a frame missing is no recording.
void App::record_frame(const std::string& dir, int frame) {
    if (framebuffer_size_.x <= 0 || framebuffer_size_.y <= 0) return;  // minimised: nothing drawn
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    save_screenshot(capture_frame(*context_, framebuffer_size_), (fs::path(dir) / name).string());
}

void App::write_outputs(const Options& options, const Image& screenshot, const FrameClock& clock,
                        int frames) {
    if (!screenshot.rgba.empty()) {
        const std::string path = options.screenshot.empty() ? "screenshots/" + step_name() + ".png" : options.screenshot;
        // Written (or thrown) before a word of the success line: "screenshot: " alone is no success.
        const std::string written = save_screenshot(screenshot, path);
        std::cout << "screenshot: " << written << "\n";
    }
    if (!options.export_dir.empty()) {  // run() refused --export where the step offers none
        export_(prepare_export_dir(options.export_dir));  // every file, or throws naming the first that failed
        std::cout << "export: " << fs::absolute(options.export_dir).string() << "\n";
    }
    if (options.bench) {
        const int timed_frames = std::max(0, clock.bench_frames(frames));
        const double bench_seconds = clock.bench_seconds();
        std::cout << timers_.report(bench_seconds, timed_frames, clock.bench_first_frame());
        if (clock.stopped())
            std::cout << "bench: the passes were timed one by one (a glFinish around each) on the last "
                      << frames - clock.bench_first_frame() - timed_frames
                      << " frames; the frames per second come from the frames before them, drawn without "
                         "those waits\n";
        // The step prints its own lines, then hands the figures.
        const BenchFigures extra = bench_figures_ ? bench_figures_() : BenchFigures{};
        std::cout << bench_csv_line(step_name(), framebuffer_size_, timers_, bench_seconds, timed_frames,
                                    extra);
    }
}

void App::hand_over_to(const std::string& step) {
    const std::string executable = step_executable(step);
    if (executable.empty()) {
        show_message(step + " is not built next to this step");
        return;
    }
    next_step_command_ = hand_over_command(executable, time_, framebuffer_size_, params_, split_view_, paused_);
    context_->request_close();
}

}  // namespace ocean
