// The panel as a headless run draws it (--ui), measured on the screenshot: a step that clears to
// one grey, run with and without the panel; the pixels that differ are the panel's. Its rectangle
// at 960x540 and 640x360 covers at most a quarter of the window, lies inside it, and is as wide as
// default_panel_rect and no taller. (Its own executable: App makes its own context.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "common/app.hpp"
#include "common/image.hpp"
#include "common/panel_state.hpp"

#include <imgui.h>

namespace fs = std::filesystem;

namespace {

class GreyStep : public ocean::App {
public:
    GreyStep() : App({"probe", "", "a step for measuring the panel"}) {
        params().add_float("level", &level_, 0, 1, "grey level of the clear colour");
        offer_split_view([] { return SplitVariants{"dark", "light", {"level=0.2"}, {"level=0.8"}}; });
    }

private:
    void render() override {
        glClearColor(level_, level_, level_, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    float level_ = 0.5f;
};

const ocean::StepLocation kWhere{"probe", OCEAN_SOURCE_DIR "/common"};

ocean::Image screenshot(const std::string& size, bool ui, bool split = false) {
    const std::string path = (fs::temp_directory_path() /
                              ("ocean_panel_" + std::to_string(::getpid()) + (ui ? "_ui.png" : ".png")))
                                 .string();
    std::vector<std::string> args{"--headless", "--size", size,           "--frames", "3",
                                  "--time",     "1",      "--screenshot", path};
    if (ui) args.push_back("--ui");
    if (split) args.push_back("--split");
    GreyStep step;
    EXPECT_EQ(step.run(args, kWhere), 0);
    std::string error;
    auto image = ocean::load_image(path, &error);
    fs::remove(path);
    EXPECT_TRUE(image.has_value()) << error;
    return image ? *image : ocean::Image{};
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inclusive
    bool empty() const { return x1 < x0; }
    double area() const { return empty() ? 0 : double(x1 - x0 + 1) * double(y1 - y0 + 1); }
};

Box differing(const ocean::Image& a, const ocean::Image& b) {
    Box box;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::size_t i = 4 * (std::size_t(y) * std::size_t(a.width) + std::size_t(x));
            int most = 0;
            for (int c = 0; c < 3; ++c)
                most = std::max(most, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
            if (most <= 8) continue;
            box.x0 = std::min(box.x0, x);
            box.y0 = std::min(box.y0, y);
            box.x1 = std::max(box.x1, x);
            box.y1 = std::max(box.y1, y);
        }
    return box;
}

TEST(PanelScreen, DefaultPanelCoversAtMostAQuarterOfTheWindowAndLiesInside) {
    for (const auto& [size, width, height] :
         {std::tuple{"960x540", 960, 540}, std::tuple{"640x360", 640, 360}}) {
        SCOPED_TRACE(size);
        const ocean::Image plain = screenshot(size, false), panel = screenshot(size, true);
        ASSERT_EQ(plain.width, width);
        ASSERT_EQ(panel.width, width);
        const Box box = differing(plain, panel);
        ASSERT_FALSE(box.empty()) << "--ui draws the panel";
        const double share = box.area() / (double(width) * double(height));
        std::cout << size << ": the panel covers " << box.x1 - box.x0 + 1 << "x" << box.y1 - box.y0 + 1
                  << " at (" << box.x0 << ", " << box.y0 << "), " << int(share * 1000 + 0.5) / 10.0
                  << " % of the window\n";
        EXPECT_LE(share, 0.25) << "most of the picture stays visible";
        EXPECT_GT(box.x0, 0);
        EXPECT_GT(box.y0, 0);
        EXPECT_LT(box.x1, width - 1) << "not cut off at the right";
        EXPECT_LT(box.y1, height - 1) << "not cut off at the bottom";
        const ocean::PanelRect want = ocean::default_panel_rect(float(width), float(height));
        EXPECT_NEAR(box.x0, want.x, 2);
        EXPECT_NEAR(box.y0, want.y, 2);
        EXPECT_NEAR(box.x1 - box.x0 + 1, want.width, 3);
        EXPECT_LE(box.y1 - box.y0 + 1, want.height + 1) << "its rows' height at most (PanelFit)";
    }
}

// The panel's first line tells a learner how to hide it: under the title bar, grey text (ImGui's
// "disabled" colour, 128 of 255, over the panel's near-black) as wide as ImGui sets kPanelHint,
// from the window's left padding. Without the hint that row holds the chapter buttons (blue).
TEST(PanelScreen, TheFirstLineSaysHowToHideThePanel) {
    const ocean::Image panel = screenshot("960x540", true);
    ASSERT_EQ(panel.width, 960);
    float hint_width = 0, title_height = 0, padding = 0;
    {
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
        ImGui::GetIO().Fonts->Build();
        ImGui::GetIO().DisplaySize = ImVec2(960, 540);
        ImGui::NewFrame();
        hint_width = ImGui::CalcTextSize(ocean::kPanelHint).x;
        title_height = ImGui::GetFontSize() + 2 * ImGui::GetStyle().FramePadding.y;
        padding = ImGui::GetStyle().WindowPadding.x;
        ImGui::EndFrame();
        ImGui::DestroyContext();
    }
    const ocean::PanelRect r = ocean::default_panel_rect(960, 540);
    // The first text row: from below the title bar, one line of text and its spacing.
    const int top = int(r.y + title_height), bottom = int(r.y + title_height + padding + 16);
    int first = 1 << 30, last = -1;
    for (int y = top; y <= bottom; ++y)
        for (int x = int(r.x); x < int(r.x + r.width); ++x) {
            const std::size_t i = 4 * (std::size_t(y) * 960 + std::size_t(x));
            const int red = panel.rgba[i], green = panel.rgba[i + 1], blue = panel.rgba[i + 2];
            const bool grey_text = red > 90 && red < 170 && std::abs(red - green) < 6 && std::abs(red - blue) < 6;
            if (grey_text) first = std::min(first, x), last = std::max(last, x);
        }
    ASSERT_GE(last, 0) << "no grey text in the panel's first row";
    std::cout << "the first row's grey text spans x " << first << " to " << last << "; the hint is "
              << hint_width << " px wide\n";
    EXPECT_NEAR(first, r.x + padding, 3) << "from the window's left padding";
    EXPECT_NEAR(last - first + 1, hint_width, 4) << "as wide as the hint";
}

// The split view beside the panel: the line between the variants at the middle of the part of the
// window the panel leaves free, so that both show as much; without the panel, the middle.
TEST(PanelScreen, SplitLineAtTheMiddleOfWhatThePanelLeavesFree) {
    const auto line_at = [](const ocean::Image& image, int y) {
        std::vector<int> white;
        for (int x = 0; x < image.width; ++x)
            if (image.rgba[4 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x))] > 250)
                white.push_back(x);
        return white;
    };
    const ocean::Image plain = screenshot("960x540", false, true), panel = screenshot("960x540", true, true);
    // A row below the panel (it ends at 10 + 432 at most) and above the labels (at the bottom).
    EXPECT_EQ(line_at(plain, 470), (std::vector<int>{479, 480})) << "no panel: the middle";
    const ocean::PanelRect r = ocean::default_panel_rect(960, 540);
    const int free_middle = int((r.x + r.width + 960) / 2 + 0.5f);  // 619
    EXPECT_EQ(line_at(panel, 470), (std::vector<int>{free_middle - 1, free_middle}))
        << "the middle of the free part, right of the panel";
    const auto grey = [&](int x) { return int(panel.rgba[4 * (std::size_t(470) * 960 + std::size_t(x))]); };
    EXPECT_LT(grey(free_middle - 20), 128) << "the left variant (dark) up to the line";
    EXPECT_GT(grey(free_middle + 20), 128) << "the right variant (light) after it";
}

}  // namespace
