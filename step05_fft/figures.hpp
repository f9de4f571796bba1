// step05's teaching figures (figures.cpp): the spectrum's lattice, the spectra, the FFT's data
// flow, one frame's passes, a fold and its Jacobian, and the bridges from step04 (the wave
// profiles, the fBm as a spectrum). ./ocean figures draws them for the lessons.
#pragma once

#include "step05_fft/spectrum.hpp"
#include "tools/figure.hpp"

namespace step05 {

figures::FigureMakers teaching_figures();

// The sea the spectrum figures show: a 14 m/s wind over 100 km, 256 modes on a 500 m tile. Inline,
// so that a later chapter's figure program shows the same sea without linking this one's.
inline SpectrumParams figure_sea() {
    SpectrumParams p;
    p.wind_speed = 14;
    p.fetch = 100000;
    p.resolution = 256;
    p.patch_size = 500;
    return p;
}

}  // namespace step05
