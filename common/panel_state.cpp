#include "common/panel_state.hpp"

#include <imgui.h>

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
constexpr std::size_t kMaxStateBytes = 64 * 1024;
}  // namespace

PanelRect default_panel_rect(float width, float height) {
    // A column at the left: about a quarter of the display wide (at least what its widgets need),
    // four fifths high (at least what shows the step and its first groups); the rest scrolls.
    PanelRect r;
    r.x = kMargin;
    r.y = kMargin;
    // Whole pixels (ImGui rounds a window's size down).
    r.width =
        std::floor(std::max(1.0f, std::min(width - 2 * kMargin, std::clamp(0.28f * width, 260.0f, 400.0f))));
    r.height = std::floor(std::max(1.0f, std::min(height - 2 * kMargin, std::max(0.8f * height, 280.0f))));
    return r;
}

bool begin_panel_window(const std::string& title) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const PanelRect r = default_panel_rect(display.x, display.y);
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(r.width, r.height), ImGuiCond_FirstUseEver);
    // A minimised window reports a display of 0 x 0: the panel keeps its size then.
    const bool sized = display.x >= 64 && display.y >= 64;
    if (sized)
        ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(200.0f, display.x), std::min(80.0f, display.y)),
                                            display);
    const bool open = ImGui::Begin(title.c_str());
    if (sized) {  // moved back inside (a display that shrank, a state saved in a larger window)
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        const ImVec2 inside(std::clamp(pos.x, 0.0f, std::max(0.0f, display.x - size.x)),
                            std::clamp(pos.y, 0.0f, std::max(0.0f, display.y - size.y)));
        if (inside.x != pos.x || inside.y != pos.y) ImGui::SetWindowPos(inside);
    }
    // ImGui draws a folded window's items on its first frame (it measures them): folded is folded.
    return open && !ImGui::IsWindowCollapsed();
}

std::optional<fs::path> panel_state_path(const std::string& step) {
    fs::path base;
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    if (xdg != nullptr && fs::path(xdg).is_absolute()) {  // the XDG spec: a relative one is ignored
        base = xdg;
    } else {
        const char* home = std::getenv("HOME");
        if (home == nullptr || *home == '\0') return std::nullopt;
        base = fs::path(home) / ".config";
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
