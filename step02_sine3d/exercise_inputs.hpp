// The directional waves the checks of steps 02 and 03 give the learner's functions, at step01's
// check time (step01_sine2d/exercise_inputs.hpp).
#pragma once

#include <vector>

#include "step01_sine2d/exercise_inputs.hpp"
#include "step02_sine3d/waves.hpp"

namespace exercises {

inline const std::vector<step02::DirectionalWave> kStep02Waves{
    {20, 14.0, 0.6, 3.0}, {75, 6.5, 0.25, 2.1}, {-40, 3.2, 0.1, 1.4}};
// step02's ripple exercise: a 7 m ring from (3, -5), 0.4 m one wavelength out, at its deep-water speed.
inline const step02::Ripple kStep02Ripple{3.0, -5.0, 7.0, 0.4, 3.3056};

}  // namespace exercises
