// The chapter's own tests (add_step's TESTS): built into <step>_tests, run by `./ocean test` as
// <step>.<suite>.<test>. Hold the CPU reference to something outside the code (a closed form, an
// invariant, what a viewer would check), then the GPU to the CPU.
#include "chapter.hpp"

#include <gtest/gtest.h>

namespace {

TEST(Chapter, CrestMovesTowardsPlusXAtItsSpeed) {
    // The crest at x = wavelength / 4 at t = 0, found by a search later on: moved by c t.
    const step10::Wave wave{8, 1, 2};
    for (double t : {0.25, 1.0}) {
        double best_x = 0, best_h = -1;
        for (double x = 0; x < 8; x += 1e-4)
            if (step10::height(wave, x, t) > best_h) best_h = step10::height(wave, x, t), best_x = x;
        EXPECT_NEAR(std::remainder(best_x - (2 + 2 * t), 8.0), 0.0, 2e-4) << "t = " << t;
    }
}

TEST(Chapter, ReducedPhaseIsTheSameAngle) {
    const step10::Wave wave{8, 1, 2};
    for (double t : {0.0, 3.7, 864000.0}) {
        const double p = step10::phase(wave, t);
        EXPECT_GE(p, 0.0);
        EXPECT_LT(p, ocean::kTwoPi);
        EXPECT_NEAR(std::sin(p), std::sin(-ocean::kTwoPi / 8 * 2 * t), 1e-6);
    }
}

}  // namespace
