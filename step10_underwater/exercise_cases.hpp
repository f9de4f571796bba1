// Exercises 2 and 3's waves (exercises.cpp), shared by the chapter's check and the program that
// runs the learner's function on the same cases: amplitudes 1 cm to 1 m, wavelengths 0.5 to 200 m,
// and for exercise 3 the sun 0 to 70 degrees from the vertical.
#pragma once

#include <cmath>

namespace step10 {

inline double case_amplitude(int index) { return 0.01 * std::pow(100.0, (index % 17) / 16.0); }
inline double case_wavenumber(int index) {
    return 2 * 3.14159265358979323846 / (0.5 * std::pow(400.0, (index % 23) / 22.0));
}

inline double case_sun_zenith(int index) { return 70 * 3.14159265358979323846 / 180 * (index % 29) / 28.0; }

}  // namespace step10
