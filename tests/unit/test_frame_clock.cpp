// The clock --bench reads: it times the steady state, after frame 0 and after a step's warm-up,
// and before the frames that time the passes one by one (stop).
// Only lower bounds on time are tested (a sleep may overrun on a busy machine, never fall short).
#include "common/gpu_timer.hpp"
#include "common/run_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace {

constexpr int kFrameMs = 10;

// Two clocks ticked in step, `frames` frames of at least kFrameMs: `steady` never warms up, `warm`
// warms up on the frames before `warm_until`.
struct TwoClocks {
    ocean::FrameClock steady{ocean::Options{}}, warm{ocean::Options{}};
};
TwoClocks run(int frames, int warm_until) {
    TwoClocks c;
    for (int frame = 0; frame < frames; ++frame) {
        c.steady.tick(frame, false, false);
        c.warm.tick(frame, false, frame < warm_until);
        std::this_thread::sleep_for(std::chrono::milliseconds(kFrameMs));
    }
    return c;
}

TEST(FrameClock, TimesFromFrameOneWithoutAWarmUp) {
    const TwoClocks c = run(5, 0);
    EXPECT_EQ(c.steady.bench_first_frame(), 1);  // frame 0 pays for compilation: not timed
    EXPECT_GE(c.steady.bench_seconds(), 4 * kFrameMs * 1e-3);
}

TEST(FrameClock, WaitsForTheWarmUpToEnd) {
    // Warming up on frames 0 to 3 (auto's backend trial): the clock starts at frame 4, three
    // frames after the steady clock.
    const TwoClocks c = run(8, 4);
    EXPECT_EQ(c.warm.bench_first_frame(), 4);
    EXPECT_GE(c.warm.bench_seconds(), 4 * kFrameMs * 1e-3);
    EXPECT_GE(c.steady.bench_seconds() - c.warm.bench_seconds(), 3 * kFrameMs * 1e-3);
}

TEST(FrameClock, ARunThatNeverLeavesItsWarmUpIsTimedFromFrameOne) {
    const TwoClocks c = run(4, 100);
    EXPECT_EQ(c.warm.bench_first_frame(), 1);
    EXPECT_GE(c.warm.bench_seconds(), 3 * kFrameMs * 1e-3);
}

TEST(FrameClock, StopEndsTheClockBeforeThePassTimedFrames) {
    // --bench's last frames time the passes one by one: the clock stops before frame 5 of 8.
    ocean::FrameClock clock{ocean::Options{}};
    for (int frame = 0; frame < 8; ++frame) {
        clock.tick(frame, false, false);
        if (frame == 5) clock.stop(frame);
        std::this_thread::sleep_for(std::chrono::milliseconds(kFrameMs));
    }
    EXPECT_TRUE(clock.stopped());
    EXPECT_EQ(clock.bench_frames(8), 4);  // frames 1 to 4
    const double seconds = clock.bench_seconds();
    EXPECT_GE(seconds, 4 * kFrameMs * 1e-3);
    std::this_thread::sleep_for(std::chrono::milliseconds(2 * kFrameMs));
    EXPECT_EQ(clock.bench_seconds(), seconds);  // the frames after the stop are not in it
}

TEST(FrameClock, AStopBeforeTheWarmUpEndsIsIgnored) {
    // Warming up until frame 6, asked to stop at 5: nothing would be timed, so the clock times to
    // the end as without a stop.
    ocean::FrameClock clock{ocean::Options{}};
    for (int frame = 0; frame < 8; ++frame) {
        clock.tick(frame, false, frame < 6);
        if (frame == 5) clock.stop(frame);
    }
    EXPECT_FALSE(clock.stopped());
    EXPECT_EQ(clock.bench_first_frame(), 6);
    EXPECT_EQ(clock.bench_frames(8), 2);
}

}  // namespace

// The median every benchmark quotes (gpu_timer.hpp): the middle value, the mean of the middle two
// for an even count, 0 for none; the order of the timings does not matter.
TEST(Median, IsTheMiddleTimingWhateverTheOrder) {
    EXPECT_EQ(ocean::median({}), 0.0);
    EXPECT_EQ(ocean::median({7.0}), 7.0);
    EXPECT_EQ(ocean::median({9.0, 1.0, 4.0}), 4.0);
    EXPECT_EQ(ocean::median({9.0, 1.0, 4.0, 100.0}), 6.5);  // one stalled frame moves it little
}
