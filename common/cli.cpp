#include "common/cli.hpp"

#include "common/text.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <cstdlib>

namespace ocean {

namespace {

std::optional<double> parse_double(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<long long> parse_integer(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size()) return std::nullopt;
    return value;
}

}  // namespace

ParseResult parse_command_line(const std::vector<std::string>& args) {
    ParseResult result;
    Options& o = result.options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& flag = args[i];
        // Flags with a value take it from the next argument or after '=' (--size=320x180).
        std::string value;
        bool has_inline_value = false;
        std::string name = flag;
        if (flag.rfind("--", 0) == 0 && flag.find('=') != std::string::npos) {
            name = flag.substr(0, flag.find('='));
            value = flag.substr(flag.find('=') + 1);
            has_inline_value = true;
        }
        auto take_value = [&](const char* what) -> bool {
            if (has_inline_value) return true;
            if (i + 1 >= args.size()) {
                result.error = name + " needs a value (" + what + ")";
                return false;
            }
            value = args[++i];
            return true;
        };
        auto bad = [&](const std::string& expected) {
            result.error = name + " expects " + expected + ", got '" + ellipsize(value, 40) + "'";
            return result;
        };
        auto no_value = [&]() {
            if (has_inline_value) result.error = name + " takes no value";
            return !has_inline_value;
        };

        // The flags that take a non-empty text.
        struct TextFlag { const char* flag; std::string Options::*member; const char* what; };
        static const TextFlag texts[] = {
            {"--preset", &Options::preset, "a preset file"}, {"--save-preset", &Options::save_preset, "a preset file"},
            {"--camera", &Options::camera, "a camera name"}, {"--export", &Options::export_dir, "a directory"},
            {"--shader-dir", &Options::shader_dir, "a directory"}, {"--record", &Options::record_dir, "a directory"}};
        // The flags that take no value, each setting one switch.
        static const std::pair<const char*, bool Options::*> switches[] = {
            {"--help", &Options::help}, {"-h", &Options::help}, {"--headless", &Options::headless},
            {"--list-params", &Options::list_params}, {"--bench", &Options::bench}, {"--ui", &Options::show_ui},
            {"--no-ui", &Options::hide_ui}, {"--paused", &Options::paused},
            {"--simulate-minimise", &Options::simulate_minimise}, {"--split", &Options::split}};
        const auto a_switch = std::find_if(std::begin(switches), std::end(switches),
                                           [&](const auto& s) { return name == s.first; });
        if (a_switch != std::end(switches)) {
            if (!no_value()) return result;
            o.*(a_switch->second) = true;
        } else if (name == "--size") {
            if (!take_value("WxH")) return result;
            const auto parts = split(lowercase(value), 'x');
            const auto w = parts.size() == 2 ? parse_integer(parts[0]) : std::nullopt;
            const auto h = parts.size() == 2 ? parse_integer(parts[1]) : std::nullopt;
            if (!w || !h) return bad("WIDTHxHEIGHT such as 1280x720");
            if (*w < 1 || *h < 1 || *w > kMaxImageSide || *h > kMaxImageSide)
                return bad("each side in [1, " + std::to_string(kMaxImageSide) + "]");
            o.width = static_cast<int>(*w);
            o.height = static_cast<int>(*h);
        } else if (name == "--frames") {
            if (!take_value("a count")) return result;
            const auto n = parse_integer(value);
            if (!n || *n < 1 || *n > 100000000) return bad("a frame count in [1, 100000000]");
            o.frames = static_cast<int>(*n);
        } else if (name == "--time" || name == "--start-at") {
            if (!take_value("seconds")) return result;
            const auto t = parse_double(value);
            if (!t || *t < 0 || *t > 1e9) return bad("a time in seconds in [0, 1e9]");
            (name == "--time" ? o.start_time : o.start_at) = *t;
        } else if (name == "--dt") {
            if (!take_value("seconds")) return result;
            const auto dt = parse_double(value);
            if (!dt || *dt < 0 || *dt > 10) return bad("a time step in seconds in [0, 10]");
            o.fixed_dt = *dt;
        } else if (name == "--screenshot") {
            if (!take_value("a .png path")) return result;
            if (value.size() < 5 || lowercase(value.substr(value.size() - 4)) != ".png")
                return bad("a path ending in .png");
            o.screenshot = value;
        } else if (name == "--set" || name == "--carry") {
            if (!take_value("name=value")) return result;
            // An empty name is no parameter: --carry, which skips the names a step lacks, would
            // otherwise take it without a word.
            const std::size_t equals = value.find('=');
            if (equals == std::string::npos || equals == 0) return bad("name=value");
            (name == "--set" ? o.sets : o.carries).push_back(value);
        } else if (const auto text = std::find_if(std::begin(texts), std::end(texts),
                                                  [&](const TextFlag& t) { return name == t.flag; });
                   text != std::end(texts)) {
            if (!take_value(text->what)) return result;
            if (value.empty()) return bad(text->what);
            o.*(text->member) = value;
        } else if (name == "--resource-log") {
            if (!take_value("a frame interval")) return result;
            const auto n = parse_integer(value);
            if (!n || *n < 1 || *n > 1000000) return bad("a frame interval in [1, 1000000]");
            o.resource_log = int(*n);
        } else {
            result.error = "unknown flag '" + ellipsize(flag, 40) + "' (--help lists the flags)";
            return result;
        }
    }
    if (o.show_ui && o.hide_ui) result.error = "--ui and --no-ui ask for opposite things: give one";
    return result;
}

std::string usage_text(const std::string& step, const std::string& description) {
    return step + ": " + description + R"(

usage: )" + step + R"( [flags]

  --headless            render offscreen through EGL (implied when DISPLAY is unset)
  --size WxH            framebuffer size in pixels (default 1280x720)
  --frames N            stop after N frames (default: run until closed; headless: 10)
  --time T              start the clock at T seconds and keep it fixed (see --dt)
  --dt S                fixed time step: the clock advances S seconds per frame
  --start-at T          a real clock that starts at T seconds (Prev/Next use it)
  --paused              start with the clock paused, as the panel's pause does (Prev/Next
                        carry the pause with it)
  --screenshot FILE.png write the last frame to FILE.png
                        (headless default: screenshots/<step>.png)
  --set name=value      set a parameter (repeatable; applied after --preset and --camera)
  --carry name=value    like --set, but ignored when this step has no such parameter
                        (Previous/Next carry the camera with it)
  --camera NAME         a view shared by the 3D steps: overview, deck, low, top
  --split               the chapter's two main variants side by side (left | right)
  --preset FILE         load parameters from a preset file
  --save-preset FILE    write the parameters (after --preset and --set) to FILE and exit
  --list-params         list the parameters with their defaults and ranges, and exit
  --bench               print per-pass GPU times and frames per second after the run
  --ui                  draw the ImGui panel in headless runs too
  --no-ui               start a window (or a page) with its panel hidden (F1 shows it)
  --resource-log N      every N frames print resident memory and live GL objects (soak tests)
  --simulate-minimise   frames 2 and 3 run as if the window were minimised (size 0), then restored
  --shader-dir DIR      read this step's shaders from DIR instead of its source folder
  --record DIR          write every frame to DIR/frame_0000.png, frame_0001.png ... (with --dt
                        for a steady clock; tools/animate makes an animation of them)
  --export DIR          write the simulated maps and their parameters to DIR after the last
                        frame (the steps that simulate maps)
  --help                this text

Mouse and keys (windowed): in step01, drag pans the plot and the wheel zooms it about the
cursor; in the 3D steps, drag orbits the camera, the wheel zooms, C switches orbit/fly camera
(WASD, Q/E, shift in fly); in step07, the arrows steer the boat and a right click pushes a body.
Every step: F1 hides the panel, F5 reloads shaders now (they also reload when their file
changes), Esc quits.
)";
}

}  // namespace ocean
