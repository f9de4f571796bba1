// The clock --bench reads: it times the steady state, after frame 0 and after a step's warm-up.
// Only lower bounds on time are tested (a sleep may overrun on a busy machine, never fall short).
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

}  // namespace
