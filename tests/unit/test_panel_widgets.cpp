// A parameter's widget in a panel as narrow as the first-use one at 640x360 (260 px, the item
// width App::draw_panel pushes): a name that fits sits at the widget's right; a longer one goes on
// its own line above it, so nothing reaches past the panel's edge, where ImGui would cut it.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "common/panel_state.hpp"
#include "common/panel_widgets.hpp"

namespace {

struct Placed {
    float top = 0, bottom = 0;  // the rows the parameter took
    float reach = 0, edge = 0;  // the furthest point the items reached, and the panel's right edge
};

Placed place(ocean::Param& param) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(640, 360);
    io.DeltaTime = 1.0f / 60.0f;
    io.Fonts->Build();
    ImGui::NewFrame();
    Placed placed;
    ocean::PanelFit fit;
    fit.begin("probe");
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);
    placed.top = ImGui::GetCursorScreenPos().y;
    ocean::param_widget(param);
    placed.bottom = ImGui::GetCursorScreenPos().y;
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    placed.reach = window->DC.CursorMaxPos.x;
    placed.edge = window->WorkRect.Max.x;
    ImGui::PopItemWidth();
    ImGui::End();
    ImGui::EndFrame();
    ImGui::DestroyContext();
    return placed;
}

TEST(PanelWidgets, ANameThatFitsSitsBesideItsSlider) {
    ocean::ParamRegistry params;
    float value = 1;
    ocean::Param& p = params.add_float("wind_speed", &value, 0, 40, "m/s");
    const Placed placed = place(p);
    EXPECT_LE(placed.reach, placed.edge);
    EXPECT_LT(placed.bottom - placed.top, 2.5f * 13) << "one row: the slider and its name";
}

TEST(PanelWidgets, ALongerNameGoesAboveItsSliderAndNothingIsCut) {
    ocean::ParamRegistry params;
    float value = 1;
    ocean::Param& p = params.add_float("foam_residual_decay_per_second", &value, 0, 1, "a long name");
    const float default_width = ocean::default_panel_rect(640, 360).width;
    ASSERT_LE(default_width, 270) << "the test's premise: a narrow first-use panel";
    const Placed placed = place(p);
    EXPECT_LE(placed.reach, placed.edge) << "the name would reach " << placed.reach - placed.edge << " px past the edge";
    EXPECT_GT(placed.bottom - placed.top, 2.5f * 13) << "two rows: the name, then the slider";
}

}  // namespace
