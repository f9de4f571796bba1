// FasterOfTwo (common/faster_of_two.hpp): the two ways take turns, and the lower median wins.
#include "common/faster_of_two.hpp"

#include <gtest/gtest.h>

namespace {

// Runs the choice as a step would: each frame the one it names, recording what that one took.
int decide(ocean::FasterOfTwo& choice, const double ms[2], int frames, int* runs_of_each) {
    for (int frame = 0; frame < frames && choice.deciding(); ++frame) {
        const int which = choice.next();
        ++runs_of_each[which];
        choice.record(which, ms[which]);
    }
    return choice.chosen();
}

TEST(FasterOfTwo, TakesTurnsThenKeepsTheFaster) {
    for (int faster : {0, 1}) {
        ocean::FasterOfTwo choice(3);
        const double ms[2] = {faster == 0 ? 10.0 : 30.0, faster == 0 ? 30.0 : 10.0};
        int runs[2] = {0, 0};
        EXPECT_EQ(decide(choice, ms, 100, runs), faster);
        EXPECT_EQ(runs[0], 3);  // three of each, no more
        EXPECT_EQ(runs[1], 3);
        EXPECT_FALSE(choice.deciding());
        EXPECT_EQ(choice.next(), faster);  // and from then on only the faster
        EXPECT_DOUBLE_EQ(choice.median_ms(faster), 10.0);
        // The log line names both, in order, their medians, the trials behind them and the winner.
        EXPECT_EQ(choice.verdict("first", "second"), faster == 0
                      ? "first 10.0 ms, second 30.0 ms a frame (median of 3): first"
                      : "first 30.0 ms, second 10.0 ms a frame (median of 3): second");
    }
}

TEST(FasterOfTwo, OneSlowTrialDoesNotDecide) {
    // The median, not the mean: one trial slowed by the machine (a first frame that compiles a
    // shader, another process) does not turn the choice.
    ocean::FasterOfTwo choice(3);
    choice.record(0, 10.0);
    choice.record(1, 12.0);
    choice.record(0, 500.0);
    choice.record(1, 12.0);
    choice.record(0, 10.0);
    EXPECT_TRUE(choice.deciding());
    choice.record(1, 12.0);
    EXPECT_EQ(choice.chosen(), 0);
    choice.record(1, 1.0);  // after the decision, records change nothing
    EXPECT_EQ(choice.chosen(), 0);
}

TEST(FasterOfTwo, TheSecondOnlyByAMargin) {
    // step06's shading: the compute shader only if twice as fast. On llvmpipe it is 1.4 times
    // slower, so no noise makes it win; on an H100 it is 20 times faster.
    const double near[2] = {10.0, 6.0}, far[2] = {10.0, 4.0};
    int runs[2] = {0, 0};
    ocean::FasterOfTwo near_choice(3, 2.0), far_choice(3, 2.0);
    EXPECT_EQ(decide(near_choice, near, 100, runs), 0) << "1.7 times faster is not enough";
    EXPECT_EQ(decide(far_choice, far, 100, runs), 1) << "2.5 times faster is";
}

}  // namespace
