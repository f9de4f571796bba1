// The flags every step shares. Parsing is a pure function of the argument list so the unit
// tests can check good and bad command lines without a GL context.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ocean {

// Exit statuses, the same for every step (README: "Exit status").
enum ExitCode { kExitOk = 0, kExitRuntimeError = 1, kExitUsage = 2, kExitGlError = 3 };

struct Options {
    bool help = false;
    bool headless = false;          // --headless, or implied when there is no display
    int width = 1280, height = 720; // --size WxH
    int frames = 0;                 // --frames N (0: until the window closes; headless: 10)
    std::optional<double> start_time;  // --time T: start the clock at T (and make it fixed)
    std::optional<double> fixed_dt;    // --dt S: advance S seconds per frame (a fixed clock)
    std::optional<double> start_at;    // --start-at T: a real clock that starts at T (Prev/Next)
    bool paused = false;            // --paused: the clock starts paused (the panel's pause; Prev/Next)
    std::string screenshot;         // --screenshot FILE.png, written after the last frame
    std::vector<std::string> sets;  // --set name=value, in order
    std::vector<std::string> carries;  // --carry name=value: set only where the step has `name`
    std::string preset;             // --preset FILE, applied before the --set values
    std::string save_preset;        // --save-preset FILE: write the parameters and exit
    bool list_params = false;
    bool bench = false;             // per-pass GPU times and frames per second after the run
    bool show_ui = false;           // --ui: draw the panel in headless runs (and screenshots)
    bool hide_ui = false;           // --no-ui: a window (or page) starts with its panel hidden
    std::string shader_dir;         // --shader-dir DIR: read this step's shaders from DIR
    std::string export_dir;         // --export DIR: a step that simulates maps writes them there
    std::string record_dir;         // --record DIR: every frame to DIR/frame_NNNN.png (animations)
    std::string camera;             // --camera NAME: a shared view (camera_presets())
    bool split = false;             // --split: the chapter's two variants side by side
    int resource_log = 0;           // --resource-log N: print memory and GL objects every N frames
    bool simulate_minimise = false; // --simulate-minimise: frames 2-3 as if the window were minimised
};

struct ParseResult {
    Options options;
    std::optional<std::string> error;  // one line, for stderr
};

ParseResult parse_command_line(const std::vector<std::string>& args);

// The --help text; `step` and `description` head it.
std::string usage_text(const std::string& step, const std::string& description);

// Largest accepted --size side: more than any GPU's framebuffer limit is surely a typo.
constexpr int kMaxImageSide = 16384;

}  // namespace ocean
