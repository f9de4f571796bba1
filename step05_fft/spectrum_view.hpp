// The panel's view of the spectrum: a plot of S(omega) with the peak marked, the numbers a
// sailor would quote (significant height, peak period and wavelength), and the 2D spectrum of
// the tile as an image (log10 of each mode's energy), also shown full screen by view=spectrum.
#pragma once

#include "common/gl.hpp"
#include "step05_fft/spectrum.hpp"

#include <string>
#include <vector>

namespace step05 {

class SpectrumView {
public:
    // Recomputes the plot and the image (call when the spectrum changes; needs a GL context).
    void update(const SpectrumParams& params, const InitialSpectrum& spectrum);
    void draw_ui() const;
    GLuint texture() const { return texture_.id(); }

private:
    std::vector<float> plot_;  // S(omega) (or its Phillips equivalent) on [0, omega_max]
    double omega_max_ = 1, peak_omega_ = 0, significant_height_ = 0, growth_law_height_ = 0, cem_height_ = 0;
    std::string model_;
    ocean::Texture texture_;
    int n_ = 0;
};

}  // namespace step05
