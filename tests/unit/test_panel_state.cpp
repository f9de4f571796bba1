// The panel's window (common/panel_state.hpp), driven through ImGui itself without a GL context
// (ImGui's core needs only a built font atlas): its first-use rectangle at 960x540 and 640x360,
// kept inside a display that shrinks, and its state carried from one run to the next through
// the file a windowed run writes.
#include <gtest/gtest.h>
#include <imgui.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/panel_state.hpp"

namespace fs = std::filesystem;

namespace {

// One ImGui context, as a run has, with frames around `body`.
struct ImGuiRun {
    ImGuiRun(float width, float height) {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(width, height);
        io.Fonts->Build();
    }
    ~ImGuiRun() { ImGui::DestroyContext(); }
    ImGuiRun(const ImGuiRun&) = delete;
    ImGuiRun& operator=(const ImGuiRun&) = delete;
    void frame(const std::function<void()>& body) {
        ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        body();
        ImGui::EndFrame();
    }
    void resize(float width, float height) { ImGui::GetIO().DisplaySize = ImVec2(width, height); }
};

struct Rect {
    ImVec2 pos, size;
    bool expanded = true;
};

// The panel's frame as App::draw_panel draws it: the rectangle it ends up with.
Rect panel_frame(ImGuiRun& run, const std::function<void()>& inside = {}) {
    Rect r;
    run.frame([&] {
        r.expanded = ocean::begin_panel_window("step05_fft");
        if (inside) inside();
        ImGui::TextUnformatted(ocean::kPanelHint);
        r.pos = ImGui::GetWindowPos();
        r.size = ImGui::GetWindowSize();
        ImGui::End();
    });
    return r;
}

void expect_inside(const Rect& r, float width, float height) {
    EXPECT_GE(r.pos.x, 0);
    EXPECT_GE(r.pos.y, 0);
    EXPECT_LE(r.pos.x + r.size.x, width);
    EXPECT_LE(r.pos.y + r.size.y, height);
}

constexpr double kMaxShare = 1.0 / 3.0;  // of the window the panel covers at first, at most

TEST(PanelWindow, DefaultCoversAtMostAThirdOfTheWindowAndLiesInside) {
    for (const ImVec2 display : {ImVec2(960, 540), ImVec2(640, 360), ImVec2(1280, 720), ImVec2(1920, 1080)}) {
        ImGuiRun run(display.x, display.y);
        Rect r;
        for (int frame = 0; frame < 3; ++frame) r = panel_frame(run);
        const double share = double(r.size.x) * double(r.size.y) / (double(display.x) * double(display.y));
        SCOPED_TRACE(std::to_string(int(display.x)) + "x" + std::to_string(int(display.y)) + ": share " +
                     std::to_string(share));
        EXPECT_TRUE(r.expanded);
        EXPECT_LE(share, kMaxShare) << "the panel leaves most of the picture visible";
        EXPECT_GE(r.size.x, 200) << "wide enough for its widgets";
        expect_inside(r, display.x, display.y);
        const ocean::PanelRect want = ocean::default_panel_rect(display.x, display.y);
        EXPECT_FLOAT_EQ(r.size.x, want.width);
        EXPECT_FLOAT_EQ(r.size.y, want.height);
    }
}

TEST(PanelWindow, KeptInsideADisplayThatShrinks) {
    ImGuiRun run(960, 540);
    panel_frame(run);
    panel_frame(run, [] {  // the user made it large and moved it to the lower right
        ImGui::SetWindowSize(ImVec2(500, 520));
        ImGui::SetWindowPos(ImVec2(450, 15));
    });
    run.resize(640, 360);
    Rect r;
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run);
    expect_inside(r, 640, 360);
    run.resize(0, 0);  // minimised: the panel keeps its size
    const Rect minimised = panel_frame(run);
    EXPECT_FLOAT_EQ(minimised.size.x, r.size.x);
    EXPECT_FLOAT_EQ(minimised.size.y, r.size.y);
}

struct PanelStateFile : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("ocean_panel_state_" + std::to_string(::getpid()));
    fs::path file = dir / "sin_waves_into_water" / "step05_fft.panel.ini";
    ~PanelStateFile() override { fs::remove_all(dir); }
};

TEST_F(PanelStateFile, AMovedAndFoldedPanelStartsTheNextRunWhereItWas) {
    std::ostringstream warnings;
    {
        ImGuiRun first(960, 540);
        ocean::PanelState state(file);
        state.load(warnings);
        panel_frame(first);
        state.save_if_wanted(warnings);  // the state the run started from
        EXPECT_FALSE(fs::exists(file)) << "nothing changed: nothing written";
        panel_frame(first, [] { ImGui::SetWindowPos(ImVec2(600, 40)); });
        ImGui::GetIO().WantSaveIniSettings = true;  // what ImGui sets a moment after a change
        state.save_if_wanted(warnings);
        ASSERT_TRUE(fs::exists(file)) << "a moved panel is remembered";
        EXPECT_FALSE(ImGui::GetIO().WantSaveIniSettings) << "cleared once saved, as ImGui asks";
        panel_frame(first, [] { ImGui::SetWindowCollapsed(true); });
        panel_frame(first);
        state.flush(warnings);  // the end of the run
    }
    {
        ImGuiRun second(960, 540);
        ocean::PanelState state(file);
        second.frame([] {});  // the panel's first frame need not be the context's first
        state.load(warnings);
        Rect r = panel_frame(second);
        EXPECT_FALSE(r.expanded) << "still folded";
        EXPECT_FLOAT_EQ(r.pos.x, 600);
        EXPECT_FLOAT_EQ(r.pos.y, 40);
    }
    EXPECT_EQ(warnings.str(), "");
}

TEST_F(PanelStateFile, ADragOfTheTitleBarIsWrittenWhenImGuiAsks) {
    std::ostringstream warnings;
    {
        ImGuiRun run(960, 540);
        ocean::PanelState state(file);
        state.load(warnings);
        const auto frame = [&] {
            panel_frame(run);
            state.save_if_wanted(warnings);  // as App::draw_panel, every frame
        };
        frame();
        frame();
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(60, 18);  // the title bar
        frame();
        io.MouseDown[0] = true;
        frame();
        for (int step = 1; step <= 10; ++step) {
            io.MousePos = ImVec2(60 + 20.0f * float(step), 18 + 10.0f * float(step));
            frame();
        }
        io.MouseDown[0] = false;
        for (int i = 0; i < 30; ++i) frame();
        EXPECT_FALSE(fs::exists(file)) << "ImGui waits io.IniSavingRate (1 s) before asking";
        for (int i = 0; i < 60; ++i) frame();
        ASSERT_TRUE(fs::exists(file)) << "written once ImGui asked (io.WantSaveIniSettings)";
    }
    ImGuiRun next(960, 540);
    ocean::PanelState state(file);
    state.load(warnings);
    const Rect r = panel_frame(next);
    // Dragged by (200, 100) from (10, 10), less ImGui's few pixels of drag threshold.
    EXPECT_NEAR(r.pos.x, 210, 4);
    EXPECT_NEAR(r.pos.y, 110, 4);
    EXPECT_EQ(warnings.str(), "");
}

TEST_F(PanelStateFile, ACorruptFileIsIgnoredWithAWarning) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << "\x7f"
                                             "ELF\x01\x02\x00garbage";
    std::ostringstream warnings;
    ImGuiRun run(960, 540);
    ocean::PanelState state(file);
    state.load(warnings);
    const Rect r = panel_frame(run);
    EXPECT_NE(warnings.str().find("warning: the panel's saved state"), std::string::npos) << warnings.str();
    EXPECT_FLOAT_EQ(r.pos.x, ocean::default_panel_rect(960, 540).x) << "started from the defaults";
    EXPECT_FALSE(ocean::is_panel_state_text("not = [ini"));
    EXPECT_FALSE(ocean::is_panel_state_text("Pos=1,2\n"));  // a line before any header
    EXPECT_TRUE(ocean::is_panel_state_text("[Window][step05_fft]\nPos=10,10\nSize=268,432\nCollapsed=0\n\n"));
    EXPECT_TRUE(ocean::is_panel_state_text(""));
}

TEST_F(PanelStateFile, AFailedWriteIsAWarningNotAnExit) {
    const fs::path blocked = dir / "a_file";
    fs::create_directories(dir);
    std::ofstream(blocked) << "in the way";
    std::ostringstream warnings;
    ImGuiRun run(960, 540);
    ocean::PanelState state(blocked / "sin_waves_into_water" / "step05_fft.panel.ini");
    state.load(warnings);
    panel_frame(run);
    state.save_if_wanted(warnings);
    panel_frame(run, [] { ImGui::SetWindowPos(ImVec2(300, 20)); });
    state.flush(warnings);
    EXPECT_NE(warnings.str().find("warning: the panel's state is not saved"), std::string::npos)
        << warnings.str();
}

TEST(PanelStatePath, XdgConfigHomeThenHomeDotConfig) {
    const char* old_xdg = std::getenv("XDG_CONFIG_HOME");
    const char* old_home = std::getenv("HOME");
    const std::string saved_xdg = old_xdg ? old_xdg : "", saved_home = old_home ? old_home : "";
    ::setenv("XDG_CONFIG_HOME", "/tmp/xdg", 1);
    ::setenv("HOME", "/home/learner", 1);
    EXPECT_EQ(ocean::panel_state_path("step01_sine2d"),
              fs::path("/tmp/xdg/sin_waves_into_water/step01_sine2d.panel.ini"));
    ::setenv("XDG_CONFIG_HOME", "relative", 1);  // the XDG spec: ignored
    EXPECT_EQ(ocean::panel_state_path("step01_sine2d"),
              fs::path("/home/learner/.config/sin_waves_into_water/step01_sine2d.panel.ini"));
    ::unsetenv("XDG_CONFIG_HOME");
    ::unsetenv("HOME");
    EXPECT_FALSE(ocean::panel_state_path("step01_sine2d").has_value());
    if (old_xdg) ::setenv("XDG_CONFIG_HOME", saved_xdg.c_str(), 1);
    if (old_home) ::setenv("HOME", saved_home.c_str(), 1);
}

}  // namespace
