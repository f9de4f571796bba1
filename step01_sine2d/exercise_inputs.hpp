// What the exercises' checks give the learner's functions (STEP/exercises.cpp): the same waves, at
// the same time, as the chapter's tests of its CPU reference (a later chapter's exercise_inputs.hpp
// adds its own waves at the same time).
#pragma once

#include <vector>

#include "step01_sine2d/sine_sum.hpp"

namespace exercises {

// The moment every check of steps 01 to 04 evaluates its waves at.
constexpr double kCheckTime = 1.7;
inline const std::vector<step01::Wave> kStep01Waves{{8.0, 0.5, 1.2}, {3.1, 0.2, -0.7}, {1.7, 0.08, 0.9}};

}  // namespace exercises
