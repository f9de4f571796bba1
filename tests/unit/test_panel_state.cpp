// The panel's window (common/panel_state.hpp), driven through ImGui itself without a GL context
// (ImGui's core needs only a built font atlas): its rectangle from 640x360 up (a quarter of the
// display at most, a readable number of rows, ending below a whole row), following a display that
// shrinks and grows, a size the user drags kept within it, its state carried from one run to the
// next through the file a windowed run writes, and the frame-time plot's ceiling.
#include <gtest/gtest.h>
#include <imgui.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/panel_state.hpp"
#include "common/platform.hpp"

#include <imgui_internal.h>  // the panel's clip rectangle (EndsBelowAWholeRowNeverAcrossOne)

namespace fs = std::filesystem;

namespace {

// One ImGui context, as a run has, with frames around `body` (the font scaled as App does), and
// the panel's PanelFit.
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
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = 1.0f / 60.0f;
        io.FontGlobalScale = ocean::panel_font_scale(io.DisplaySize.x, io.DisplaySize.y);
        ImGui::NewFrame();
        body();
        ImGui::EndFrame();
    }
    void resize(float width, float height) { ImGui::GetIO().DisplaySize = ImVec2(width, height); }
    ocean::PanelFit fit;
};

struct Rect {
    ImVec2 pos, size;
    bool expanded = true;
};

// The panel's frame as App::draw_panel draws it: the rectangle it ends up with. `rows` rows of
// text after the hint, each noted as the panel notes its rows.
Rect panel_frame(ImGuiRun& run, const std::function<void()>& inside = {}, int rows = 0) {
    Rect r;
    run.frame([&] {
        r.expanded = run.fit.begin("step05_fft");
        if (inside) inside();
        ImGui::TextUnformatted(ocean::kPanelHint);
        run.fit.note_row();
        for (int i = 0; i < rows; ++i) {
            ImGui::Text("row %d", i);
            run.fit.note_row();
        }
        r.pos = ImGui::GetWindowPos();
        r.size = ImGui::GetWindowSize();
        if (r.expanded) run.fit.end();
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

constexpr double kMaxShare = 0.25;  // of the window the panel covers, at most

// The sizes a learner's window has, from the smallest the panel is made for (640x360) up.
const ImVec2 kDisplays[] = {ImVec2(640, 360), ImVec2(640, 400), ImVec2(800, 450),   ImVec2(960, 540),
                            ImVec2(1024, 768), ImVec2(1280, 720), ImVec2(1366, 768), ImVec2(1920, 1080),
                            ImVec2(2560, 1440), ImVec2(3840, 2160)};

std::string size_name(ImVec2 display) { return std::to_string(int(display.x)) + "x" + std::to_string(int(display.y)); }

TEST(PanelWindow, AtMostAQuarterOfTheWindowInsideItWithReadableRows) {
    for (const ImVec2 display : kDisplays) {
        ImGuiRun run(display.x, display.y);
        Rect r;
        for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);  // more than fits
        const double share = double(r.size.x) * double(r.size.y) / (double(display.x) * double(display.y));
        SCOPED_TRACE(size_name(display) + ": share " + std::to_string(share));
        EXPECT_TRUE(r.expanded);
        EXPECT_LE(share, kMaxShare) << "the panel leaves most of the picture visible";
        EXPECT_GE(r.size.x, 200) << "wide enough for its widgets";
        expect_inside(r, display.x, display.y);
        const ocean::PanelRect most = ocean::default_panel_rect(display.x, display.y);
        EXPECT_FLOAT_EQ(r.size.x, most.width);
        EXPECT_LE(r.size.y, most.height);
        // Readable: ImGui's 13 px font never smaller, and at least kMinPanelRows rows of text
        // between the title bar and the bottom padding.
        EXPECT_GE(ImGui::GetFontSize(), 13.0f);
        const ImGuiStyle& style = ImGui::GetStyle();
        const float title = ImGui::GetFontSize() + 2 * style.FramePadding.y;
        const float rows = (r.size.y - title - 2 * style.WindowPadding.y) / ImGui::GetTextLineHeightWithSpacing();
        EXPECT_GE(rows, float(ocean::kMinPanelRows)) << rows << " rows of " << ImGui::GetFontSize() << " px text";
    }
    EXPECT_FLOAT_EQ(ocean::panel_font_scale(1280, 720), 1.0f);
    EXPECT_FLOAT_EQ(ocean::panel_font_scale(640, 360), 1.0f) << "never below ImGui's 13 px";
    EXPECT_FLOAT_EQ(ocean::panel_font_scale(1920, 1080), 1.5f) << "a large display, larger text";
}

// The rows' top and bottom edges (from the display's top) in a panel of text lines, buttons and a
// wrapped paragraph; then the bottom of what ImGui shows of them (its clip rectangle).
struct Rows {
    std::vector<std::pair<float, float>> edges;
    float clip_bottom = 0;
};

Rows mixed_panel_frame(ImGuiRun& run) {
    Rows rows;
    run.frame([&] {
        run.fit.begin("step05_fft");
        const auto keep = [&] { rows.edges.emplace_back(ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().y); };
        for (int i = 0; i < 40; ++i) {
            ImGui::Text("row %d", i);
            keep();
            run.fit.note_row();
            ImGui::Button("a button");
            keep();
            run.fit.note_row();
            ImGui::PushTextWrapPos(0);
            ImGui::TextUnformatted("a paragraph that wraps over several lines of the panel, as a chapter's description");
            const float line = ImGui::GetTextLineHeight();
            for (float y = ImGui::GetItemRectMin().y; y + 1 < ImGui::GetItemRectMax().y; y += line)
                rows.edges.emplace_back(y, y + line);
            run.fit.note_text_lines();
            ImGui::PopTextWrapPos();
        }
        rows.clip_bottom = ImGui::GetCurrentWindow()->InnerClipRect.Max.y;
        run.fit.end();
        ImGui::End();
    });
    return rows;
}

TEST(PanelWindow, EndsBelowAWholeRowNeverAcrossOne) {
    for (const ImVec2 display : kDisplays) {
        SCOPED_TRACE(size_name(display));
        ImGuiRun run(display.x, display.y);
        Rows rows;
        for (int frame = 0; frame < 3; ++frame) rows = mixed_panel_frame(run);
        int shown = 0;
        for (const auto& [top, bottom] : rows.edges) {
            EXPECT_TRUE(bottom <= rows.clip_bottom || top >= rows.clip_bottom)
                << "a row from " << top << " to " << bottom << " is cut at " << rows.clip_bottom;
            if (bottom <= rows.clip_bottom) ++shown;
        }
        EXPECT_GE(shown, ocean::kMinPanelRows);
        EXPECT_LT(shown, int(rows.edges.size())) << "the test's premise: more rows than fit";
    }
}

TEST(PanelWindow, AShortPanelEndsBelowItsLastRow) {
    ImGuiRun run(1280, 720);
    Rect r;
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 3);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float title = ImGui::GetFontSize() + 2 * style.FramePadding.y;
    // The title bar, the padding above, four rows (the hint and three), the padding below.
    const float want = title + style.WindowPadding.y + 4 * ImGui::GetTextLineHeightWithSpacing() -
                       style.ItemSpacing.y + style.WindowPadding.y;
    EXPECT_NEAR(r.size.y, want, 1.0f);
}

// The issue: after a shrink the panel kept its short height in the larger window.
TEST(PanelWindow, FollowsTheDisplayAsItShrinksAndGrows) {
    ImGuiRun run(960, 540);
    const auto settle = [&] {
        Rect r;
        for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);
        return r;
    };
    Rect r = settle();
    for (const ImVec2 display : {ImVec2(640, 360), ImVec2(1920, 1080), ImVec2(960, 540), ImVec2(640, 400)}) {
        run.resize(display.x, display.y);
        const Rect before = r;
        r = settle();
        SCOPED_TRACE(size_name(display));
        const ocean::PanelRect most = ocean::default_panel_rect(display.x, display.y);
        EXPECT_FLOAT_EQ(r.size.x, most.width);
        EXPECT_LE(r.size.y, most.height);
        EXPECT_GE(r.size.y, most.height - ImGui::GetTextLineHeightWithSpacing()) << "from " << before.size.y;
        expect_inside(r, display.x, display.y);
    }
}

TEST(PanelWindow, KeptInsideADisplayThatShrinks) {
    ImGuiRun run(960, 540);
    panel_frame(run);
    panel_frame(run, [] {  // moved to the lower right
        ImGui::SetWindowPos(ImVec2(650, 200));
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

// A size the user drags (the lower right corner's grip) is the user's: kept while the display
// allows, cut to a smaller display, and whole again when it grows back.
TEST(PanelWindow, ASizeTheUserDragsIsKeptWithinTheDisplay) {
    ImGuiRun run(960, 540);
    Rect r;
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 grip(r.pos.x + r.size.x - 3, r.pos.y + r.size.y - 3);
    io.MousePos = grip;
    panel_frame(run, {}, 200);
    io.MouseDown[0] = true;
    panel_frame(run, {}, 200);
    for (int step = 1; step <= 10; ++step) {
        io.MousePos = ImVec2(grip.x + 20.0f * float(step), grip.y + 5.0f * float(step));
        panel_frame(run, {}, 200);
    }
    io.MouseDown[0] = false;
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);
    ASSERT_TRUE(run.fit.user_sized());
    const ImVec2 dragged = r.size;
    EXPECT_NEAR(dragged.x, ocean::default_panel_rect(960, 540).width + 200, 2) << "wider by the drag";
    run.resize(400, 300);
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);
    expect_inside(r, 400, 300);
    run.resize(960, 540);
    for (int frame = 0; frame < 3; ++frame) r = panel_frame(run, {}, 200);
    EXPECT_FLOAT_EQ(r.size.x, dragged.x) << "the user's size again";
    EXPECT_FLOAT_EQ(r.size.y, dragged.y);
}

TEST(FramePlot, TheCeilingIsTheNextRoundValueAboveTheFrames) {
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(0.0f), 1.0f);
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(0.4f), 1.0f);
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(1.01f), 2.0f);
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(16.7f), 20.0f) << "60 fps";
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(33.4f), 50.0f) << "30 fps";
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(51.0f), 100.0f);
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(333.0f), 500.0f) << "3 fps, where 50 ms was a flat line";
    EXPECT_FLOAT_EQ(ocean::frame_time_ceiling_ms(1058.7f), 2000.0f);
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
    ocean::platform::set_environment("XDG_CONFIG_HOME", "/tmp/xdg");
    ocean::platform::set_environment("HOME", "/home/learner");
    EXPECT_EQ(ocean::panel_state_path("step01_sine2d"),
              fs::path("/tmp/xdg/sin_waves_into_water/step01_sine2d.panel.ini"));
    ocean::platform::set_environment("XDG_CONFIG_HOME", "relative");  // the XDG spec: ignored
    EXPECT_EQ(ocean::panel_state_path("step01_sine2d"),
              fs::path("/home/learner/.config/sin_waves_into_water/step01_sine2d.panel.ini"));
    ocean::platform::set_environment("XDG_CONFIG_HOME", std::nullopt);
    ocean::platform::set_environment("HOME", std::nullopt);
    const char* old_app_data = std::getenv("APPDATA");
    const std::string saved_app_data = old_app_data ? old_app_data : "";
    ocean::platform::set_environment("APPDATA", "C:\\Users\\learner\\AppData\\Roaming");  // Windows: no HOME
    EXPECT_EQ(ocean::panel_state_path("step01_sine2d"),
              fs::path("C:\\Users\\learner\\AppData\\Roaming") / "sin_waves_into_water" / "step01_sine2d.panel.ini");
    ocean::platform::set_environment("APPDATA", std::nullopt);
    EXPECT_FALSE(ocean::panel_state_path("step01_sine2d").has_value());
    if (old_xdg) ocean::platform::set_environment("XDG_CONFIG_HOME", saved_xdg);
    if (old_home) ocean::platform::set_environment("HOME", saved_home);
    if (old_app_data) ocean::platform::set_environment("APPDATA", saved_app_data);
}

}  // namespace
