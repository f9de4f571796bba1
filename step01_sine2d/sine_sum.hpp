// Chapter 1 on the CPU, in double precision: the reference the GPU plot is tested against.
//
//   f(x, t) = sum_i a_i sin(x w_i - t phi_i),   w = 2 pi / wavelength,   phi = speed * 2 pi / wavelength
//
// A crest sits where x w - t phi is constant: x = (const + t phi) / w, so it travels towards +x at
// phi / w = speed. The notes write + t phi, which moves its crests towards -x (see README).
//
// The notes write w = 2 / wavelength; a sine repeats every 2 pi radians, so only 2 pi / wavelength
// makes the wave repeat every `wavelength` metres (see README).
#pragma once

#include "common/constants.hpp"

#include <cmath>
#include <vector>

namespace step01 {

using ocean::kTwoPi;

struct Wave {
    double wavelength = 1;  // metres between crests
    double amplitude = 0;   // metres from rest to crest
    double speed = 0;       // metres per second the crests travel (towards +x for speed > 0)
};

// w: radians per metre.
inline double angular_wavenumber(const Wave& wave) { return kTwoPi / wave.wavelength; }
// phi: radians per second.
inline double phase_rate(const Wave& wave) { return wave.speed * kTwoPi / wave.wavelength; }

// The phase term -t * phi reduced to [0, 2 pi): the GPU gets it in single precision and adds it
// to x w, so it stays exact however long the program runs (t * phi itself, in a float, is 1/1024
// rad coarse after an hour and 1/64 rad after a day for a 9 m wave). Every sum-of-waves step (02,
// 04) uses this one.
inline double phase_at(double phase_rate, double time) {
    const double phase = std::fmod(-time * phase_rate, kTwoPi);
    return phase < 0 ? phase + kTwoPi : phase;
}

inline double wave_height(const Wave& wave, double x, double time) {
    return wave.amplitude * std::sin(x * angular_wavenumber(wave) - time * phase_rate(wave));
}

inline double sum_of_sines(const std::vector<Wave>& waves, double x, double time) {
    double height = 0;
    for (const Wave& wave : waves) height += wave_height(wave, x, time);
    return height;
}

// df/dx, which the plot uses to keep its lines the same width on steep slopes.
inline double sum_of_sines_slope(const std::vector<Wave>& waves, double x, double time) {
    double slope = 0;
    for (const Wave& wave : waves) {
        const double w = angular_wavenumber(wave);
        slope += wave.amplitude * w * std::cos(x * w - time * phase_rate(wave));
    }
    return slope;
}

// d2f/dx2, how fast the slope turns (the curvature where slopes are gentle): the plot draws it with
// show_curvature.
inline double sum_of_sines_curvature(const std::vector<Wave>& waves, double x, double time) {
    double curvature = 0;
    for (const Wave& wave : waves) {
        const double w = angular_wavenumber(wave);
        curvature -= wave.amplitude * w * w * std::sin(x * w - time * phase_rate(wave));
    }
    return curvature;
}

}  // namespace step01
