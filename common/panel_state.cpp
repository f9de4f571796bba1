#include "common/panel_state.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // the window's cursor, scroll and full size (PanelFit)

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <system_error>

#include "common/file_output.hpp"
#include "common/text.hpp"

namespace ocean {

namespace fs = std::filesystem;

namespace {
constexpr float kMargin = 10;  // from the display's edges
constexpr float kFontPixels = 13;  // ImGui's default font (ProggyClean)
constexpr std::size_t kMaxStateBytes = 64 * 1024;
}  // namespace

float panel_font_scale(float width, float height) {
    const float display = std::min(width / 1280.0f, height / 720.0f);
    return std::clamp(std::floor(display * 4.0f) / 4.0f, 1.0f, 2.0f);
}

PanelRect default_panel_rect(float width, float height) {
    const float scale = panel_font_scale(width, height);
    // ImGui's default style: a title bar of the font and 2 x 3 px, 8 px of padding above and
    // below the rows, a row of text the font and 4 px.
    const float font = kFontPixels * scale;
    const float rows_height = (font + 6) + 2 * 8 + float(kMinPanelRows) * (font + 4);
    PanelRect r;
    r.x = kMargin;
    r.y = kMargin;
    // Whole pixels (ImGui rounds a window's size down).
    r.width = std::floor(
        std::max(1.0f, std::min(width - 2 * kMargin, std::clamp(0.28f * width, 260.0f * scale, 400.0f * scale))));
    const float quarter_height = 0.25f * width * height / r.width;
    r.height = std::floor(
        std::max(1.0f, std::min(height - 2 * kMargin, std::max(std::min(0.8f * height, quarter_height), rows_height))));
    return r;
}

float frame_time_ceiling_ms(float most_ms) {
    float ceiling = 1;
    for (int decade = 0; decade < 12; ++decade, ceiling *= 10)  // up to 10^12 ms: past any frame
        for (const float step : {1.0f, 2.0f, 5.0f})
            if (step * ceiling >= most_ms) return step * ceiling;
    return ceiling;
}

bool PanelFit::begin(const std::string& title) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const PanelRect r = default_panel_rect(display.x, display.y);
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_FirstUseEver);
    // A minimised window reports a display of 0 x 0: the panel keeps its size then.
    const bool sized = display.x >= 64 && display.y >= 64;
    if (sized) {
        // Every frame, so that it follows the display both ways; the user's size within it.
        set_width_ = user_sized_ ? std::min(wanted_width_, display.x) : r.width;
        set_height_ = user_sized_ ? std::min(wanted_height_, display.y) : fitted_height(r.height);
        ImGui::SetNextWindowSize(ImVec2(set_width_, set_height_), ImGuiCond_Always);
        ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(200.0f, display.x), std::min(80.0f, display.y)),
                                            display);
    }
    const bool open = ImGui::Begin(title.c_str());
    const ImGuiStyle& style = ImGui::GetStyle();
    padding_ = style.WindowPadding.y;
    spacing_ = style.ItemSpacing.y;
    border_ = style.WindowBorderSize;
    ends_.clear();
    bottom_ = 0;
    if (sized) {
        // A size other than the one asked for is the user's (the resize grip, applied in Begin);
        // its full size, not the title bar of a folded panel.
        const ImVec2 full = ImGui::GetCurrentWindow()->SizeFull;
        if (std::abs(full.x - set_width_) > 0.5f || std::abs(full.y - set_height_) > 0.5f) {
            user_sized_ = true;
            wanted_width_ = full.x;
            wanted_height_ = full.y;
        }
        // Moved back inside (a display that shrank, a state saved in a larger window).
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        const ImVec2 inside(std::clamp(pos.x, 0.0f, std::max(0.0f, display.x - size.x)),
                            std::clamp(pos.y, 0.0f, std::max(0.0f, display.y - size.y)));
        if (inside.x != pos.x || inside.y != pos.y) ImGui::SetWindowPos(inside);
    }
    // ImGui draws a folded window's items on its first frame (it measures them): folded is folded.
    return open && !ImGui::IsWindowCollapsed();
}

// ImGui clips a window's rows one border width above its bottom edge (InnerClipRect): a panel that
// ends a border below a row's last pixel shows all of it and nothing of the next.
void PanelFit::note_row() {
    // The cursor waits at the next row, one spacing below this one's bottom; from the window's
    // top as if scrolled to its start.
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    const float next_row = window->DC.CursorPos.y - window->Pos.y + window->Scroll.y;
    bottom_ = std::max(bottom_, next_row - spacing_);
    ends_.push_back(next_row);
}

void PanelFit::note_text_lines() {
    // A wrapped text's lines follow each other with no spacing, one font height apart.
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    const float line = ImGui::GetTextLineHeight();
    const float top = ImGui::GetItemRectMin().y - window->Pos.y + window->Scroll.y;
    const float bottom = ImGui::GetItemRectMax().y - window->Pos.y + window->Scroll.y;
    for (float y = top + line; y <= bottom + 0.5f; y += line) ends_.push_back(y + border_);
    bottom_ = std::max(bottom_, bottom);
}

void PanelFit::end() {
    last_ends_ = ends_;
    last_bottom_ = bottom_;
}

float PanelFit::fitted_height(float most) const {
    if (last_ends_.empty()) return most;  // the first frame: its rows are not known yet
    // All of it, with the window's padding below, where it fits; else down to the lowest row that
    // fits, ending where the next one starts.
    if (last_bottom_ + padding_ <= most) return std::floor(last_bottom_ + padding_ + 0.5f);
    float height = 0;
    for (const float end : last_ends_)
        if (end <= most) height = std::max(height, end);
    return height > 0 ? std::floor(height) : most;
}

std::optional<fs::path> panel_state_path(const std::string& step) {
    fs::path base;
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    if (xdg != nullptr && fs::path(xdg).is_absolute()) {  // the XDG spec: a relative one is ignored
        base = xdg;
    } else {
        const char* home = std::getenv("HOME");
        if (home != nullptr && *home != '\0') {
            base = fs::path(home) / ".config";
        } else if (const char* app_data = std::getenv("APPDATA"); app_data != nullptr && *app_data != '\0') {
            base = app_data;  // Windows, where no HOME is set: the user's roaming settings
        } else {
            return std::nullopt;
        }
    }
    return base / "sin_waves_into_water" / (step + ".panel.ini");
}

bool is_panel_state_text(const std::string& text) {
    if (text.size() > kMaxStateBytes) return false;
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\r' && c != '\t') return false;
    bool in_section = false;
    for (std::string line : split(text, '\n')) {
        line = trim(line);
        if (line.empty()) continue;
        if (line.front() == '[') {
            // "[Type][Name]"
            const std::size_t close = line.find(']');
            if (close == std::string::npos || close == 1 || close + 1 >= line.size() ||
                line[close + 1] != '[' || line.back() != ']')
                return false;
            in_section = true;
        } else if (!in_section || line.find('=') == std::string::npos || line.front() == '=') {
            return false;
        }
    }
    return true;
}

void PanelState::load(std::ostream& warnings) {
    if (loaded_ || !file_) return;
    loaded_ = true;
    ImGui::GetIO().IniSavingRate = 1.0f;  // ImGui's 5 s would lose a change made just before closing
    std::error_code error;
    if (!fs::exists(*file_, error)) return;  // the first run of this step: the defaults
    std::string text;
    if (auto problem = read_text_file(file_->string(), &text, kMaxStateBytes)) {
        warnings << "warning: the panel's saved state is ignored: " << *problem << "\n";
        return;
    }
    if (!is_panel_state_text(text)) {
        warnings << "warning: the panel's saved state '" << file_->string()
                 << "' is not ImGui settings text: ignored (the panel starts at its defaults)\n";
        return;
    }
    ImGui::LoadIniSettingsFromMemory(text.data(), text.size());
}

void PanelState::save_if_wanted(std::ostream& warnings) {
    ImGuiIO& io = ImGui::GetIO();
    if (!baseline_) {
        baseline_ = ImGui::SaveIniSettingsToMemory();
        io.WantSaveIniSettings = false;
        return;
    }
    if (!io.WantSaveIniSettings) return;
    io.WantSaveIniSettings = false;
    flush(warnings);
}

void PanelState::flush(std::ostream& warnings) {
    if (!baseline_ || !file_) return;  // never drawn: nothing the user could have changed
    const std::string text = ImGui::SaveIniSettingsToMemory();
    if (text == (written_ ? *written_ : *baseline_)) return;
    write(text, warnings);
}

void PanelState::write(const std::string& text, std::ostream& warnings) {
    written_ = text;  // a failure is not retried every second
    std::error_code error;
    fs::create_directories(file_->parent_path(), error);
    std::optional<std::string> problem;
    if (error)
        problem = "cannot create '" + file_->parent_path().string() + "': " + error.message();
    else
        problem = write_file(*file_, text, "panel state");
    if (problem && !warned_) {
        warnings << "warning: the panel's state is not saved: " << *problem << "\n";
        warned_ = true;
    }
}

}  // namespace ocean
