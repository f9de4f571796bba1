// The ImGui panel every step shows: who the step is, how fast it runs, its parameters (drawn
// from the registry, so a new parameter needs no UI code), presets, shader errors, and then
// the step's own ui() hook.
#include "common/app.hpp"
#include "common/panel_widgets.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>

namespace ocean {

bool param_widget(Param& p) {
    const char* label = p.name().c_str();
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

bool param_widgets(ParamRegistry& params) {
    bool changed = false;
    std::string open_group;
    bool group_open = true;
    const auto& all = params.all();
    for (std::size_t i = 0; i < all.size(); ++i) {
        const auto& p = all[i];
        if (p->group() != open_group) {
            open_group = p->group();
            // A group whose parameters are all hidden (wave 7 of 3) gets no header at all.
            bool any_visible = false;
            for (std::size_t j = i; j < all.size() && all[j]->group() == open_group; ++j)
                any_visible = any_visible || all[j]->visible();
            // Ungrouped parameters are always shown; groups start folded to keep the panel short.
            group_open = open_group.empty() || (any_visible && ImGui::CollapsingHeader(open_group.c_str()));
        }
        if (!group_open || !p->visible()) continue;
        if (param_widget(*p)) changed = true;
    }
    return changed;
}

void App::draw_panel(float frame_ms) {
    GLFWwindow* window = context_->window();
    if (window != nullptr && !ImGui::GetIO().WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_F1)) panel_visible_ = !panel_visible_;
        if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) context_->request_close();
        if (ImGui::IsKeyPressed(GLFW_KEY_F5))
            programs_.rebuild_all();
        if (camera_enabled_ && ImGui::IsKeyPressed(GLFW_KEY_C)) {
            camera_.mode = camera_.mode == Camera::Orbit ? Camera::Fly : Camera::Orbit;
        }
    }
    if (!panel_visible_) return;

    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    // As tall as the screen allows; the panel scrolls when a step has more to show.
    ImGui::SetNextWindowSize(ImVec2(390, ImGui::GetIO().DisplaySize.y - 20), ImGuiCond_FirstUseEver);
    ImGui::Begin(step_name().c_str());
    // Previous / next chapter, at the same moment and with the same view (bgfx's example dialog).
    const auto& steps = all_steps();
    const auto here = std::find(steps.begin(), steps.end(), step_name());
    if (here != steps.end()) {
        const bool has_previous = here != steps.begin(), has_next = here + 1 != steps.end();
        if (!has_previous) ImGui::BeginDisabled();
        if (ImGui::Button(has_previous ? ("< " + *(here - 1)).c_str() : "< (first)")) hand_over_to(*(here - 1));
        if (!has_previous) ImGui::EndDisabled();
        ImGui::SameLine();
        if (!has_next) ImGui::BeginDisabled();
        if (ImGui::Button(has_next ? (*(here + 1) + " >").c_str() : "(last) >")) hand_over_to(*(here + 1));
        if (!has_next) ImGui::EndDisabled();
    }
    ImGui::TextUnformatted(info_.title.c_str());
    ImGui::TextDisabled("%s", info_.notes_label().c_str());
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(info_.description.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Separator();

    static constexpr int kHistory = 120;
    static std::array<float, kHistory> history{};  // ImGui's plot wants a plain array
    static int cursor = 0;
    history[std::size_t(cursor++ % kHistory)] = frame_ms;
    ImGui::Text("%.2f ms/frame (%.0f fps), %dx%d", double(frame_ms),
                frame_ms > 0 ? 1000.0 / double(frame_ms) : 0.0, framebuffer_size_.x, framebuffer_size_.y);
    // ImGui 1.86's plots take no negative width ("fill"): pass the width that is left.
    ImGui::PlotLines("##frame_ms", history.data(), kHistory, cursor % kHistory, nullptr, 0, 50,
                     ImVec2(ImGui::GetContentRegionAvail().x, 40));
    ImGui::Text("t = %.3f s", time_);
    ImGui::SameLine();
    ImGui::Checkbox("pause", &paused_);

    if (split_variants_) {
        const SplitVariants variants = split_variants_();
        ImGui::Checkbox("split view", &split_view_);
        if (split_view_) {
            ImGui::SameLine();
            ImGui::TextDisabled("left: %s | right: %s", variants.left_label.c_str(), variants.right_label.c_str());
            // Labels on the picture itself, at the top of each half.
            ImDrawList* draw = ImGui::GetBackgroundDrawList();
            const float middle = 0.5f * float(framebuffer_size_.x);
            draw->AddText(ImVec2(middle - 8 - ImGui::CalcTextSize(variants.left_label.c_str()).x, 8),
                          IM_COL32(255, 255, 255, 255), variants.left_label.c_str());
            draw->AddText(ImVec2(middle + 8, 8), IM_COL32(255, 255, 255, 255), variants.right_label.c_str());
        }
    }
    ImGui::Separator();
    param_widgets(params_);
    if (ImGui::Button("reset to defaults")) params_.reset_all();
    std::array<char, 256> path{};
    preset_path_.copy(path.data(), path.size() - 1);
    if (ImGui::InputText("preset file", path.data(), path.size())) preset_path_ = path.data();
    if (ImGui::Button("load preset")) {
        const auto error = params_.load_preset(preset_path_);
        show_message(error ? *error : "loaded " + preset_path_);
    }
    ImGui::SameLine();
    if (ImGui::Button("save preset")) {
        const auto error = params_.save_preset(preset_path_, step_name() + " preset");
        show_message(error ? *error : "saved " + preset_path_);
    }

    ui();

    // Two channels: the shaders' build problems (ProgramLibrary's own state, cleared when they
    // build again) and the framework's last message (show_message).
    for (const std::string* message : std::array<const std::string*, 2>{&programs_.message(), &panel_message_}) {
        if (message->empty()) continue;
        ImGui::Separator();
        ImGui::PushTextWrapPos(0);
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", message->c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

}  // namespace ocean
