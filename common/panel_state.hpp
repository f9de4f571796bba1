// The panel's window: its size, fitted to the display and to its rows, and its state between runs.
//
// The panel is an ordinary ImGui window: collapsible (its title bar's arrow), movable (drag the
// title bar) and resizable (its lower right corner). Until the user resizes it, its size is
// fitted every frame (PanelFit), so it follows the window as it grows or shrinks: at most
// default_panel_rect(), a column at the left that covers at most a quarter of the picture from
// 640x360 up and shows at least kMinPanelRows rows of text, and no taller than its rows (it ends
// below a whole row, never across one; the rest scrolls). Its font grows with the display
// (panel_font_scale). A size the user drags is kept for the run, within the display, and comes
// back whole when the display grows again after a shrink. The panel is moved back inside a
// display that shrinks, so it is never cut off.
//
// A windowed run remembers the panel (position, collapsed; ImGui writes its size too, which the
// next run fits anew) per step in
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
#include <vector>

namespace ocean {

struct PanelRect {
    float x = 0, y = 0, width = 0, height = 0;
    float area() const { return width * height; }
};

// The hint the panel shows on its first line.
inline constexpr const char* kPanelHint = "F1 hides this panel";

// The rows of text the panel shows at least, at its largest (the rest scrolls).
inline constexpr int kMinPanelRows = 10;

// The scale of ImGui's 13 px font in a display of `width` x `height`: 1 up to 1280x720 (never
// smaller: the pixel font blurs and shrinks past reading), then with the display, in quarters
// (1.5 at 1920x1080), at most 2.
float panel_font_scale(float width, float height);

// The panel's largest rectangle in a display of `width` x `height` (ImGui's coordinates): at the
// upper left, about 28 % of the display wide (at least what its widgets need), 80 % high, no more
// than a quarter of the display's area, never past its edges; at least kMinPanelRows rows high
// where the display allows.
PanelRect default_panel_rect(float width, float height);

// The frame-time plot's ceiling in milliseconds for frames up to `most_ms`: the next of
// 1, 2, 5, 10, 20, 50 ... at or above it, so the plot uses its height and the ceiling reads easily.
float frame_time_ceiling_ms(float most_ms);

// The panel's window frame by frame: its size fitted (see the top of this file) until the user
// resizes it, kept inside the display. App::draw_panel owns one.
class PanelFit {
public:
    // Begins the panel's ImGui window `title` (pair it with ImGui::End, whatever it returns, as
    // ImGui::Begin). Returns false when it is folded (collapsed).
    bool begin(const std::string& title);
    // After the last item of a row (several items on one line: the last): the panel may end
    // below it.
    void note_row();
    // After a text item that wraps: below each of its lines.
    void note_text_lines();
    // Before ImGui::End of an expanded panel: the rows noted are the next frame's.
    void end();
    bool user_sized() const { return user_sized_; }

private:
    // The height that ends below a whole row, at most `most`.
    float fitted_height(float most) const;
    // The heights at which the panel may end, below a whole row, and the lowest row's bottom: from
    // the window's top, scrolled to its start; this frame's and the last frame's.
    std::vector<float> ends_, last_ends_;
    float bottom_ = 0, last_bottom_ = 0;
    float padding_ = 0, spacing_ = 0, border_ = 0;  // ImGui's style: bottom padding, rows' spacing, border
    bool user_sized_ = false;
    float set_width_ = 0, set_height_ = 0;        // what begin() asked for this frame
    float wanted_width_ = 0, wanted_height_ = 0;  // the user's size
};

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
