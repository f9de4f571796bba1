// The parameters of one wave of a sum: waveN_wavelength, waveN_amplitude and waveN_speed, in the
// panel group "wave N", shown while N < wave_count. step01 declares them for its plot; a sea whose
// waves also have a direction declares its own through the same function, with its own ranges.
#pragma once

#include "common/params.hpp"

#include <functional>
#include <string>

namespace step01 {

struct WaveSliders {
    float wavelength = 1, amplitude = 0, speed = 0;  // metres, metres, metres per second
};

struct WaveRanges {
    float max_wavelength, max_amplitude, max_speed;
    const char* speed_help;
};

// Declares wave `index`, bound to `wave`, whose current values are the defaults.
inline void declare_wave(ocean::ParamRegistry& p, int index, WaveSliders& wave, const WaveRanges& ranges,
                         std::function<bool()> visible) {
    const std::string prefix = "wave" + std::to_string(index) + "_";
    const std::string group = "wave " + std::to_string(index);
    p.add_float(prefix + "wavelength", &wave.wavelength, 0.1f, ranges.max_wavelength, "distance between crests, metres")
        .in_group(group).visible_if(visible).logarithmic();
    p.add_float(prefix + "amplitude", &wave.amplitude, 0, ranges.max_amplitude, "height of a crest above rest, metres")
        .in_group(group).visible_if(visible);
    p.add_float(prefix + "speed", &wave.speed, -ranges.max_speed, ranges.max_speed, ranges.speed_help)
        .in_group(group).visible_if(visible);
}

}  // namespace step01
