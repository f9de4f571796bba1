// The run loop of ocean::App, driven the way a step is: a headless run with a GL error exits 3,
// the fixed clock gives the times --time and --dt promise, --save-preset writes a preset that
// loads back, and a screenshot is written. (Its own executable: App makes its own context.)
#include "common/app.hpp"
#include "common/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace {

class ProbeStep : public ocean::App {
public:
    ProbeStep() : App({"probe", "", "a step for testing the framework"}) {
        params().add_float("level", &level_, 0, 1, "grey level of the clear colour");
        params().add_bool("make_gl_error", &make_gl_error_, "call GL with a bad enum once");
    }
    std::vector<double> times;
    std::string hand_over_after_first_frame;
    std::vector<double> dts;
    int rendered = 0;

private:
    void update(double time, double dt) override {
        times.push_back(time);
        dts.push_back(dt);
        if (!hand_over_after_first_frame.empty() && times.size() == 1) hand_over_to(hand_over_after_first_frame);
    }
    void render() override {
        ++rendered;
        glClearColor(level_, level_, level_, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        // Some texture, so the screenshot is not a flat colour.
        glEnable(GL_SCISSOR_TEST);
        for (int i = 0; i < 8; ++i) {
            glScissor(i * 4, i * 2, 4, 2);
            glClearColor(float(i) / 8.0f, 0.5f, 1.0f - float(i) / 8.0f, 1);
            glClear(GL_COLOR_BUFFER_BIT);
        }
        glDisable(GL_SCISSOR_TEST);
        if (make_gl_error_) glEnable(GL_TEXTURE_1D_ARRAY);  // not a capability: GL_INVALID_ENUM
    }
    float level_ = 0.25f;  // its default
    bool make_gl_error_ = false;
};

const ocean::StepLocation kWhere{"probe", OCEAN_SOURCE_DIR "/common"};

std::string temp(const std::string& name) {
    return (fs::temp_directory_path() / ("ocean_app_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(App, FixedClockStartsAtTimeAndAdvancesByDt) {
    ProbeStep step;
    ASSERT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "4", "--time", "2", "--dt", "0.5"}, kWhere), 0);
    EXPECT_EQ(step.times, (std::vector<double>{2.0, 2.5, 3.0, 3.5}));
    EXPECT_EQ(step.rendered, 4);
}

TEST(App, TimeAloneHoldsTheClock) {
    ProbeStep step;
    ASSERT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "3", "--time", "1.5"}, kWhere), 0);
    EXPECT_EQ(step.times, (std::vector<double>{1.5, 1.5, 1.5}));
}

TEST(App, HeadlessRunWithAGlErrorExitsThree) {
    ProbeStep step;
    EXPECT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "2", "--set", "make_gl_error=true"}, kWhere),
              ocean::kExitGlError);
}

TEST(App, ScreenshotIsTheLastFrame) {
    const std::string path = temp("shot.png");
    ProbeStep step;
    ASSERT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "2", "--set", "level=1",
                        "--screenshot", path}, kWhere), 0);
    std::string error;
    const auto image = ocean::load_image(path, &error);
    ASSERT_TRUE(image) << error;
    EXPECT_EQ(image->width, 32);
    EXPECT_EQ(image->height, 16);
    // Top-left pixel: the clear colour (white); the scissored squares are at the bottom left.
    EXPECT_EQ(image->rgba[0], 255);
    const std::size_t bottom_left = std::size_t(15 * 32) * 4;
    EXPECT_EQ(image->rgba[bottom_left + 1], 128);  // green 0.5 of the first square
    fs::remove(path);
}

TEST(App, SavePresetWritesTheValuesAndLoadsBack) {
    const std::string path = temp("probe.preset");
    {
        ProbeStep step;
        ASSERT_EQ(step.run({"--set", "level=0.75", "--save-preset", path}, kWhere), 0);
        EXPECT_EQ(step.rendered, 0) << "--save-preset exits before rendering";
    }
    ProbeStep step;
    ASSERT_EQ(step.run({"--headless", "--size", "8x8", "--frames", "1", "--preset", path,
                        "--screenshot", temp("p.png")}, kWhere), 0);
    std::string error;
    const auto image = ocean::load_image(temp("p.png"), &error);
    ASSERT_TRUE(image) << error;
    EXPECT_NEAR(image->rgba[0], 191, 1) << "level 0.75 came back from the preset";
    fs::remove(path);
    fs::remove(temp("p.png"));
}

TEST(App, NextStepStartsAtTheSameTimeSizeAndView) {
    ProbeStep step;
    step.hand_over_after_first_frame = "step02_sine3d";
    ASSERT_EQ(step.run({"--headless", "--size", "48x32", "--frames", "5", "--time", "2.5", "--split"}, kWhere), 0);
    EXPECT_EQ(step.rendered, 1) << "the step ends after the frame that chose its neighbour";
    const auto& next = step.next_step_command();
    ASSERT_FALSE(next.empty());
    EXPECT_NE(next[0].find("step02_sine3d/step02_sine3d"), std::string::npos) << next[0];
    const std::string args = [&] { std::string a; for (const auto& s : next) a += s + " "; return a; }();
    EXPECT_NE(args.find("--start-at 2.500000"), std::string::npos) << args;
    EXPECT_NE(args.find("--size 48x32"), std::string::npos) << args;
    EXPECT_NE(args.find("--split"), std::string::npos) << args;
    EXPECT_EQ(ocean::run_next_step(3, {}), 3) << "no neighbour chosen: the status passes through";
}

// The panel's pause travels too: a paused step starts its neighbour with --paused, and --paused
// holds the clock from the first frame (a fixed --dt would otherwise advance it).
TEST(App, APausedStepStartsItsNeighbourPaused) {
    // One App at a time (each holds ImGui's context and a GL context): one block each.
    const auto carries_pause = [](std::vector<std::string> args) {
        ProbeStep step;
        step.hand_over_after_first_frame = "step02_sine3d";
        EXPECT_EQ(step.run(args, kWhere), 0);
        const auto& next = step.next_step_command();
        EXPECT_FALSE(next.empty());
        return std::find(next.begin(), next.end(), "--paused") != next.end();
    };
    EXPECT_TRUE(carries_pause({"--headless", "--size", "16x16", "--frames", "3", "--start-at", "2", "--paused"}))
        << "a paused step starts its neighbour paused";
    EXPECT_FALSE(carries_pause({"--headless", "--size", "16x16", "--frames", "2"}))
        << "a running step starts its neighbour running";
    {
        ProbeStep paused;
        ASSERT_EQ(paused.run({"--headless", "--size", "16x16", "--frames", "3", "--time", "1", "--dt", "0.1",
                              "--paused"}, kWhere), 0);
        EXPECT_EQ(paused.times, (std::vector<double>{1, 1, 1})) << "the clock does not advance";
    }
}

TEST(App, CarriedParametersApplyOnlyWhereTheStepHasThem) {
    // Previous/Next pass the camera as --carry: a step without a camera ignores it, a step with
    // the parameter takes it (and refuses a bad value like --set).
    ProbeStep step;
    EXPECT_EQ(step.run({"--headless", "--size", "8x8", "--frames", "1", "--carry", "camera_yaw=10",
                        "--carry", "level=0.75", "--screenshot", temp("carry.png")}, kWhere), 0);
    std::string error;
    const auto image = ocean::load_image(temp("carry.png"), &error);
    ASSERT_TRUE(image) << error;
    EXPECT_NEAR(image->rgba[0], 191, 1) << "level 0.75 was carried";
    ProbeStep again;
    EXPECT_EQ(again.run({"--carry", "level=2"}, kWhere), ocean::kExitUsage) << "out of range, as with --set";
    fs::remove(temp("carry.png"));
}

TEST(App, BadInputIsRefusedBeforeAnyContextIsMade) {
    ProbeStep step;
    EXPECT_EQ(step.run({"--set", "level=2"}, kWhere), ocean::kExitUsage);
    EXPECT_EQ(step.run({"--frames"}, kWhere), ocean::kExitUsage);
    EXPECT_EQ(step.rendered, 0);
}

// A step whose split variants set `level`, and which notes the level each update() sees.
class SplitProbe : public ocean::App {
public:
    explicit SplitProbe(bool update_each_side) : App({"split probe", "", "a step for testing the split view"}) {
        params().add_float("level", &level_, 0, 1, "grey level of the clear colour");
        offer_split_view([update_each_side] {
            SplitVariants variants{"dark", "light", {"level=0.2"}, {"level=0.8"}};
            variants.update_each_side = update_each_side;
            return variants;
        });
    }
    std::vector<float> levels_updated;
    int rendered = 0;

private:
    void update(double, double) override { levels_updated.push_back(level_); }
    void render() override {
        ++rendered;
        glClearColor(level_, level_, level_, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    float level_ = 0.5f;
};

TEST(App, SplitViewUpdatesOnceAFrameWithTheUsersParameters) {
    SplitProbe step(false);
    ASSERT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "2", "--split"}, kWhere), 0);
    EXPECT_EQ(step.levels_updated, (std::vector<float>{0.5f, 0.5f}));
    EXPECT_EQ(step.rendered, 4);
}

// A variant that changes what update() computes (step05's transform backend) gets its own update.
TEST(App, SplitViewWhoseSidesUpdateEachSideUpdatesBeforeEachRender) {
    SplitProbe step(true);
    ASSERT_EQ(step.run({"--headless", "--size", "32x16", "--frames", "2", "--split"}, kWhere), 0);
    EXPECT_EQ(step.levels_updated, (std::vector<float>{0.2f, 0.8f, 0.2f, 0.8f}));
    EXPECT_EQ(step.rendered, 4);
}

}  // namespace
