// The command line every step shares: good and bad flags.
#include "common/cli.hpp"

#include <gtest/gtest.h>

namespace {

ocean::ParseResult parse(std::vector<std::string> args) { return ocean::parse_command_line(args); }

TEST(CommandLine, DefaultsWithNoFlags) {
    const auto r = parse({});
    ASSERT_FALSE(r.error);
    EXPECT_FALSE(r.options.headless);
    EXPECT_EQ(r.options.width, 1280);
    EXPECT_EQ(r.options.frames, 0);
    EXPECT_FALSE(r.options.start_time);
}

TEST(CommandLine, TheSmokeTestCommandLine) {
    const auto r = parse({"--headless", "--frames", "3", "--time", "1.5", "--size", "320x180",
                          "--screenshot", "out/a.png", "--set", "amplitude=2", "--set=wave_count=4"});
    ASSERT_FALSE(r.error) << *r.error;
    EXPECT_TRUE(r.options.headless);
    EXPECT_EQ(r.options.frames, 3);
    EXPECT_DOUBLE_EQ(*r.options.start_time, 1.5);
    EXPECT_EQ(r.options.width, 320);
    EXPECT_EQ(r.options.height, 180);
    EXPECT_EQ(r.options.screenshot, "out/a.png");
    EXPECT_EQ(r.options.sets, (std::vector<std::string>{"amplitude=2", "wave_count=4"}));
}

TEST(CommandLine, NoUiHidesThePanelAndContradictsUi) {
    EXPECT_TRUE(parse({"--no-ui"}).options.hide_ui);
    const auto both = parse({"--ui", "--no-ui"});
    ASSERT_TRUE(both.error);
    EXPECT_NE(both.error->find("--ui and --no-ui"), std::string::npos) << *both.error;
}

TEST(CommandLine, PausedStartsTheClockPausedAndTakesNoValue) {
    EXPECT_FALSE(parse({}).options.paused);
    EXPECT_TRUE(parse({"--paused"}).options.paused);
    const auto valued = parse({"--paused=1"});
    ASSERT_TRUE(valued.error);
    EXPECT_EQ(*valued.error, "--paused takes no value");
}

TEST(CommandLine, OtherFlags) {
    const auto r = parse({"--dt", "0.02", "--bench", "--list-params", "--preset", "p.txt",
                          "--save-preset", "q.txt", "--ui", "--shader-dir", "/tmp/s", "--export", "out", "--help"});
    ASSERT_FALSE(r.error) << *r.error;
    EXPECT_DOUBLE_EQ(*r.options.fixed_dt, 0.02);
    EXPECT_TRUE(r.options.bench && r.options.list_params && r.options.show_ui && r.options.help);
    EXPECT_EQ(r.options.preset, "p.txt");
    EXPECT_EQ(r.options.save_preset, "q.txt");
    EXPECT_EQ(r.options.shader_dir, "/tmp/s");
    EXPECT_EQ(r.options.export_dir, "out");
}

TEST(CommandLine, BadInputGetsOneLineNamingTheFlag) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--nope"}, "unknown flag '--nope'"},
        {{"-x"}, "unknown flag '-x'"},
        {{"positional"}, "unknown flag 'positional'"},
        {{"--size", "0x0"}, "--size expects each side in [1, 16384]"},
        {{"--size", "100000x10"}, "--size expects each side"},
        {{"--size", "abc"}, "--size expects WIDTHxHEIGHT"},
        {{"--size", "-5x10"}, "--size expects each side"},
        {{"--size"}, "--size needs a value"},
        {{"--frames", "0"}, "--frames expects a frame count"},
        {{"--frames", "ten"}, "--frames expects a frame count"},
        {{"--time", "nan"}, "--time expects a time"},
        {{"--time", "-1"}, "--time expects a time"},
        {{"--dt", "inf"}, "--dt expects a time step"},
        {{"--screenshot", "a.jpg"}, "--screenshot expects a path ending in .png"},
        {{"--set", "amplitude"}, "--set expects name=value"},
        {{"--carry", "=5"}, "--carry expects name=value, got '=5'"},
        {{"--set", "=5"}, "--set expects name=value"},
        {{"--headless=yes"}, "--headless takes no value"},
        {{"--preset", ""}, "--preset expects a preset file"},
    };
    for (const auto& [args, expected] : cases) {
        const auto r = parse(args);
        ASSERT_TRUE(r.error) << args.front();
        EXPECT_NE(r.error->find(expected), std::string::npos) << *r.error;
        EXPECT_EQ(r.error->find('\n'), std::string::npos);
    }
}

TEST(CommandLine, UsageListsEveryFlag) {
    const std::string usage = ocean::usage_text("step", "desc");
    for (const char* flag : {"--headless", "--size", "--frames", "--time", "--dt", "--screenshot", "--set",
                             "--preset", "--save-preset", "--list-params", "--bench", "--help", "--start-at",
                             "--paused", "--split", "--carry", "--no-ui"})
        EXPECT_NE(usage.find(flag), std::string::npos) << flag;
}

}  // namespace
