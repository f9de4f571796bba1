// The panel's window: where it starts, how it stays on screen, and its state between runs.
//
// The panel is an ordinary ImGui window: collapsible (its title bar's arrow), movable (drag the
// title bar) and resizable (its lower right corner). It starts at default_panel_rect(): a column
// at the left about a quarter of the window wide, which leaves most of the picture visible at
// 960x540 and 640x360; every frame its size is kept within the display and it is moved back
// inside when the display shrinks, so it is never cut off (its contents scroll).
//
// A windowed run remembers the panel (position, size, collapsed) per step in
// $XDG_CONFIG_HOME/sin_waves_into_water/STEP.panel.ini (~/.config/... without XDG_CONFIG_HOME):
// read before the panel's first frame (ImGui's LoadIniSettingsFromMemory; io.IniFilename stays
// null, so ImGui writes no imgui.ini of its own) and written through write_file when ImGui asks
// (io.WantSaveIniSettings), only once the user changed something. Headless runs, tests and
// benchmarks neither read nor write it: their pictures stay reproducible. A file that cannot be
// written is a warning; a file that is not ImGui settings text is ignored with a warning.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace ocean {

struct PanelRect {
    float x = 0, y = 0, width = 0, height = 0;
    float area() const { return width * height; }
};

// The hint the panel shows on its first line.
inline constexpr const char* kPanelHint = "F1 hides this panel";

// The panel's first-use rectangle in a display of `width` x `height` (ImGui's coordinates).
PanelRect default_panel_rect(float width, float height);

// Begins the panel's ImGui window `title` (pair it with ImGui::End, whatever it returns, as
// ImGui::Begin): first-use rectangle, size clamped to the display, moved back inside it.
// Returns false when it is folded (collapsed).
bool begin_panel_window(const std::string& title);

// $XDG_CONFIG_HOME (when absolute) or $HOME/.config, then sin_waves_into_water/STEP.panel.ini;
// nothing when neither is set.
std::optional<std::filesystem::path> panel_state_path(const std::string& step);

// Whether `text` reads as ImGui's settings text ("[Type][Name]" headers and "key=value" lines,
// printable, at most 64 KiB).
bool is_panel_state_text(const std::string& text);

// The panel's persistence in a windowed run (App makes one with its ImGui context, in windowed
// runs only, and flushes it before destroying the context).
class PanelState {
public:
    explicit PanelState(std::optional<std::filesystem::path> file) : file_(std::move(file)) {}
    // Before the panel's first ImGui::Begin (in its frame): feeds ImGui the file's settings, if
    // any; a file that is unreadable or not settings text is ignored with a warning on `warnings`.
    // Once: later calls do nothing.
    void load(std::ostream& warnings);
    // After the panel's window ended: remembers the settings the run starts from (first call),
    // and writes them when ImGui asks and they differ from those and from the last written.
    // A failed write is a warning (once).
    void save_if_wanted(std::ostream& warnings);
    // Writes now if the settings changed (at the end of a run).
    void flush(std::ostream& warnings);

private:
    void write(const std::string& text, std::ostream& warnings);
    std::optional<std::filesystem::path> file_;
    std::optional<std::string> baseline_, written_;
    bool loaded_ = false, warned_ = false;
};

}  // namespace ocean
