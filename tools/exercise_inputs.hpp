// The inputs the exercises of steps 01 to 03 share: the same waves, at the same time, as the
// chapters' tests of their CPU references.
#pragma once

#include "step01_sine2d/sine_sum.hpp"
#include "step02_sine3d/waves.hpp"

#include <vector>

namespace exercises {

// The waves the checks of steps 01 to 03 give the learner's functions, at t = 1.7 s.
constexpr double kCheckTime = 1.7;
inline const std::vector<step01::Wave> kStep01Waves{{8.0, 0.5, 1.2}, {3.1, 0.2, -0.7}, {1.7, 0.08, 0.9}};
inline const std::vector<step02::DirectionalWave> kStep02Waves{{20, 14.0, 0.6, 3.0}, {75, 6.5, 0.25, 2.1}, {-40, 3.2, 0.1, 1.4}};

}  // namespace exercises
