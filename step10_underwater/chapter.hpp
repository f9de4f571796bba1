// The chapter's math on the CPU, in double precision: the reference its tests hold the GPU to,
// and the truth they check it against. Replace it with your chapter's technique.
//
// The template draws one travelling wave, h(x, t) = a sin(w x - w c t), w = 2 pi / wavelength:
// its crests move towards +x at c metres per second (step01's convention).
#pragma once

#include "common/constants.hpp"

#include <cmath>

namespace step10 {  // `./ocean new` names it after the folder: step10 for step10_spray

struct Wave {
    double wavelength = 8;  // metres
    double amplitude = 1;   // metres
    double speed = 2;       // metres per second, towards +x
};

inline double height(const Wave& wave, double x, double time) {
    const double w = ocean::kTwoPi / wave.wavelength;
    return wave.amplitude * std::sin(w * (x - wave.speed * time));
}

// The phase -w c t reduced to [0, 2 pi) in double precision: the GPU adds it to w x in float.
inline double phase(const Wave& wave, double time) {
    const double p = std::fmod(-ocean::kTwoPi / wave.wavelength * wave.speed * time, ocean::kTwoPi);
    return p < 0 ? p + ocean::kTwoPi : p;
}

}  // namespace step10
