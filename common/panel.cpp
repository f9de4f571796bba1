// The ImGui panel every step shows: who the step is, how fast it runs, its parameters (drawn
// from the registry, so a new parameter needs no UI code), presets, shader errors, and then
// the step's own ui() hook.
#include "common/app.hpp"
#include "common/panel_state.hpp"
#include "common/panel_widgets.hpp"
#include "common/param_groups.hpp"
#include "common/text.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the window's extent this frame (report_overflow)

#include <algorithm>
#include <array>
#include <functional>
#include <iostream>

namespace ocean {

bool param_widget(Param& p) {
    const char* label = p.name().c_str();
    // A widget's label sits at its right, in the room the panel's item width leaves; a name longer
    // than that goes on its own line above the widget, where a narrow panel does not cut it.
    std::string hidden_label;
    if (p.type() != ParamType::Bool) {
        const float room = ImGui::GetContentRegionAvail().x - ImGui::CalcItemWidth() - ImGui::GetStyle().ItemInnerSpacing.x;
        if (ImGui::CalcTextSize(label).x > room) {
            ImGui::TextUnformatted(label);
            hidden_label = "##" + p.name();
            label = hidden_label.c_str();
        }
    }
    bool changed = false;
    switch (p.type()) {
        // The widgets edit a copy; set_number clamps it to the registry's range (typed values,
        // ctrl-click, can leave a slider's) and tells the parameter's generations.
        case ParamType::Float: {
            if (p.is_double_precision()) {  // a coordinate: typed to the millimetre, not dragged in float steps
                double value = p.number();
                changed = ImGui::InputDouble(label, &value, 1.0, 1000.0, "%.3f");
                if (changed) p.set_number(value);
                break;
            }
            float value = float(p.number());
            changed = ImGui::SliderFloat(label, &value, float(p.min()), float(p.max()), "%.3g",
                                         p.is_logarithmic() ? ImGuiSliderFlags_Logarithmic : 0);
            if (changed) p.set_number(value);
            break;
        }
        case ParamType::Int: {
            int value = int(p.number());
            changed = ImGui::SliderInt(label, &value, int(p.min()), int(p.max()));
            if (changed) p.set_number(value);
            break;
        }
        case ParamType::Bool: {
            bool value = p.number() != 0;
            changed = ImGui::Checkbox(label, &value);
            if (changed) p.set_number(value ? 1 : 0);
            break;
        }
        case ParamType::Choice: {
            const auto& choices = p.choices();
            const int value = int(p.number());
            if (ImGui::BeginCombo(label, choices[std::size_t(value)].c_str())) {
                for (int i = 0; i < int(choices.size()); ++i)
                    if (ImGui::Selectable(choices[std::size_t(i)].c_str(), i == value)) {
                        p.set_number(i);
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            break;
        }
        case ParamType::Color:
            changed = ImGui::ColorEdit3(label, &p.color_value()->x);
            if (changed) p.bump_generations();
            break;
        case ParamType::Text: {
            std::array<char, 1025> buffer{};
            p.text_value()->copy(buffer.data(), buffer.size() - 1);
            // Applied on Enter, through the registry's own check.
            if (ImGui::InputText(label, buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue))
                changed = !p.set_from_text(buffer.data()).has_value();
            break;
        }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\nrange %s, default %s", p.help().c_str(),
                                                  p.range_text().c_str(), p.default_text().c_str());
    return changed;
}

bool param_widgets(ParamRegistry& params, const std::function<void()>& after_each_row) {
    bool changed = false;
    // One header per group, in the order the groups first appear, with every parameter of the
    // group under it wherever it was declared (param_groups.hpp).
    for (const ParamGroup& group : group_params(params.all())) {
        // A group whose parameters are all hidden (wave 7 of 3) gets no header at all.
        const bool any_visible = std::any_of(group.params.begin(), group.params.end(),
                                             [](const Param* p) { return p->visible(); });
        if (!any_visible) continue;
        // Ungrouped parameters are always shown; groups start folded to keep the panel short.
        const bool open = group.name.empty() || ImGui::CollapsingHeader(group.name.c_str());
        if (!group.name.empty() && after_each_row) after_each_row();
        if (!open) continue;
        for (Param* p : group.params) {
            if (!p->visible()) continue;
            if (param_widget(*p)) changed = true;
            if (after_each_row) after_each_row();
        }
    }
    return changed;
}

// The split view beside the panel: the halves divide at the middle of the widest part of the
// window the panel leaves free (from the next frame's render on), so that both variants show as
// much; the labels sit at the bottom of each half, over everything. A folded panel, or one that
// leaves less than a third free, changes nothing: the middle.
static void split_beside_panel(SplitView& split, const SplitVariants& variants, glm::ivec2 framebuffer_size,
                               ImVec2 panel_pos, ImVec2 panel_size, bool expanded) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    if (display.x < 1 || framebuffer_size.x < 1) return;
    float from = 0, to = display.x;  // the free span, ImGui's coordinates
    if (expanded) {
        const float left_free = std::max(0.0f, panel_pos.x);
        const float right_free = display.x - (panel_pos.x + panel_size.x);
        if (std::max(left_free, right_free) >= display.x / 3) {
            if (right_free >= left_free) from = panel_pos.x + panel_size.x;
            else to = panel_pos.x;
        }
    }
    const float divide = 0.5f * (from + to);
    const float scale = float(framebuffer_size.x) / display.x;  // framebuffer pixels per ImGui unit
    split.set_divide(int(divide * scale + 0.5f));
    draw_split_labels(variants, divide);
}

// What reaches past the panel's right edge is cut off there (ImGui clips it; the panel has no
// horizontal scrolling): a status line that ends mid-word. A headless --ui run (the screenshots,
// the tests), whose panel has its first-use width, names the first part of the panel that does, as
// a warning for the chapter's author; a learner who narrows the panel in a window is not warned.
// ImGui's window keeps the furthest point its items reached this frame (DC.CursorMaxPos) and the
// right edge of its work area (WorkRect): a part overflows when the first passes the second.
static bool report_overflow(const char* part) {
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    const float overflow = window->DC.CursorMaxPos.x - window->WorkRect.Max.x;
    if (overflow <= 1) return false;
    std::cerr << "warning: panel: " << part << " reaches " << int(overflow + 0.5f)
              << " px past the panel's right edge and is cut off there\n";
    return true;
}

void App::draw_panel(float frame_ms) {
    // The keys (F1, Esc, F5, C) are handled before this, from the window's events (app_input.cpp).
    if (!panel_visible_) {
        // The split view's labels stay (at the window's middle, where the line is without the
        // panel); they show where App::frame renders ImGui's draw data with the panel hidden.
        if (split_view_ && split_variants_)
            draw_split_labels(split_variants_(), 0.5f * ImGui::GetIO().DisplaySize.x);
        return;
    }

    // A window a learner moves, resizes and folds, kept on screen (panel_state.hpp); a windowed
    // run starts it where the last one left it and remembers it (never a headless run: its
    // pictures stay reproducible).
    PanelState* state = panel_state_.get();
    if (state != nullptr) state->load(std::cerr);
    PanelFit& fit = *panel_fit_;
    const bool expanded = fit.begin(step_name());
    const ImVec2 panel_pos = ImGui::GetWindowPos(), panel_size = ImGui::GetWindowSize();
    if (!expanded) {
        ImGui::End();
        if (state != nullptr) state->save_if_wanted(std::cerr);
        if (split_view_ && split_variants_)
            split_beside_panel(split_, split_variants_(), framebuffer_size_, panel_pos, panel_size, false);
        return;
    }
    // Each part checked as it is drawn (headless runs only, once a run).
    const auto check = [&](const char* part) {
        if (context_->window() == nullptr && !panel_overflow_reported_)
            panel_overflow_reported_ = report_overflow(part);
    };
    // The rows noted as they are drawn are the places the panel may end (PanelFit), never across one.
    const auto row = [&fit] { fit.note_row(); };
    ImGui::TextDisabled("%s", kPanelHint);
    row();
    // Widgets leave room for their labels (snake_case names up to 15 characters or so).
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);
    // Previous / next chapter, at the same moment and with the same view (bgfx's example dialog).
    const auto& steps = all_steps();
    const auto here = std::find(steps.begin(), steps.end(), step_name());
    if (here != steps.end()) {
        const bool has_previous = here != steps.begin(), has_next = here + 1 != steps.end();
        if (!has_previous) ImGui::BeginDisabled();
        if (ImGui::Button(has_previous ? ("< " + *(here - 1)).c_str() : "< (first)")) hand_over_to(*(here - 1));
        if (!has_previous) ImGui::EndDisabled();
        // Beside it where it fits, else below: a narrow panel cuts no button.
        const std::string next_label = has_next ? *(here + 1) + " >" : "(last) >";
        const ImGuiStyle& style = ImGui::GetStyle();
        const float next_width = ImGui::CalcTextSize(next_label.c_str()).x + 2 * style.FramePadding.x;
        if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + next_width <=
            ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
            ImGui::SameLine();
        else
            row();
        if (!has_next) ImGui::BeginDisabled();
        if (ImGui::Button(next_label.c_str())) hand_over_to(*(here + 1));
        if (!has_next) ImGui::EndDisabled();
        row();
    }
    ImGui::TextUnformatted(info_.title.c_str());
    row();
    ImGui::TextDisabled("%s", info_.notes_label().c_str());
    row();
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(info_.description.c_str());
    fit.note_text_lines();
    ImGui::PopTextWrapPos();
    check("the chapter's buttons and description");
    ImGui::Separator();

    static constexpr int kHistory = 120;
    static std::array<float, kHistory> history{};  // ImGui's plot wants a plain array
    static int cursor = 0;
    history[std::size_t(cursor++ % kHistory)] = frame_ms;
    ImGui::TextWrapped("%.2f ms/frame (%.0f fps), %dx%d", double(frame_ms),
                       frame_ms > 0 ? 1000.0 / double(frame_ms) : 0.0, framebuffer_size_.x, framebuffer_size_.y);
    fit.note_text_lines();
    // The plot's top follows the frames it shows (a slow machine's 500 ms frames are not a flat
    // line along a fixed top), and says what it is.
    const float ceiling = frame_time_ceiling_ms(*std::max_element(history.begin(), history.end()));
    const std::string top = "top " + format_number(double(ceiling)) + " ms";
    // ImGui 1.86's plots take no negative width ("fill"): pass the width that is left.
    ImGui::PlotLines("##frame_ms", history.data(), kHistory, cursor % kHistory, top.c_str(), 0, ceiling,
                     ImVec2(ImGui::GetContentRegionAvail().x, 3 * ImGui::GetTextLineHeight()));
    row();
    ImGui::Text("t = %.3f s", time_);
    ImGui::SameLine();
    ImGui::Checkbox("pause", &paused_);
    row();

    if (split_variants_) {
        const SplitVariants variants = split_variants_();
        ImGui::Checkbox("split view", &split_view_);
        row();
        if (split_view_) {
            ImGui::PushTextWrapPos(0);
            ImGui::TextDisabled("left: %s | right: %s", variants.left_label.c_str(), variants.right_label.c_str());
            fit.note_text_lines();
            ImGui::PopTextWrapPos();
        }
    }
    check("the frame line or the split view's labels");
    ImGui::Separator();
    param_widgets(params_, row);
    if (ImGui::Button("reset to defaults")) params_.reset_all();
    row();
    std::array<char, 256> path{};
    preset_path_.copy(path.data(), path.size() - 1);
    if (ImGui::InputText("preset file", path.data(), path.size())) preset_path_ = path.data();
    row();
    if (ImGui::Button("load preset")) {
        const auto error = params_.load_preset(preset_path_);
        show_message(error ? *error : "loaded " + preset_path_);
    }
    ImGui::SameLine();
    if (ImGui::Button("save preset")) {
        const auto error = params_.save_preset(preset_path_, step_name() + " preset");
        show_message(error ? *error : "saved " + preset_path_);
    }
    row();

    check("the parameters or the preset buttons");
    ImGui::PushTextWrapPos(0);  // the step's lines wrap at the panel's edge, however narrow it is
    ui();
    ImGui::PopTextWrapPos();
    row();  // the step's lines as one block: the panel ends above them or below them all
    check("the step's own lines (its ui())");

    // Two channels: the shaders' build problems (ProgramLibrary's own state, cleared when they
    // build again) and the framework's last message (show_message).
    for (const std::string* message : std::array<const std::string*, 2>{&programs_.message(), &panel_message_}) {
        if (message->empty()) continue;
        ImGui::Separator();
        ImGui::PushTextWrapPos(0);
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", message->c_str());
        fit.note_text_lines();
        ImGui::PopTextWrapPos();
    }
    check("a message");
    ImGui::PopItemWidth();
    fit.end();
    ImGui::End();
    if (state != nullptr) state->save_if_wanted(std::cerr);
    if (split_view_ && split_variants_)
        split_beside_panel(split_, split_variants_(), framebuffer_size_, panel_pos, panel_size, true);
}


}  // namespace ocean
