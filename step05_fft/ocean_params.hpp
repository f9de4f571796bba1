// The parameters of chapter 4's spectrum, declared once for every step that simulates it
// (step05, and step06's cascades), with the names the README and presets use. Each one is bound
// to the SpectrumParams field the math reads, so there is nothing to copy: the defaults are the
// struct's own (a step that wants another sea sets the fields before declare()).
#pragma once

#include "common/params.hpp"
#include "step05_fft/spectrum.hpp"

namespace step05 {

class OceanParams {
public:
    SpectrumParams sea;
    float choppiness = 1;  // lambda: not in the spectrum (changing it makes no new h0)
    // Bumped by every spectrum parameter: h0 needs recomputing when it moved.
    ocean::Generation changes;

    void declare(ocean::ParamRegistry& p) {
        auto spectrum = [this](ocean::Param& param) -> ocean::Param& { return param.in_group("spectrum").bumps(changes); };
        spectrum(p.add_choice("model", &sea.model, {"jonswap", "phillips"},
                              "spectrum: JONSWAP (fetch-limited wind sea) or Phillips"));
        spectrum(p.add_float("wind_speed", &sea.wind_speed, 0, 50, "wind speed at 10 m, m/s (0: a flat sea)"));
        spectrum(p.add_float("wind_direction", &sea.wind_direction, 0, 360,
                             "direction the wind blows towards, degrees (0 = +x, 90 = +z)"));
        spectrum(p.add_float("fetch", &sea.fetch, 1000, 5000000, "open water upwind, metres (JONSWAP)")).logarithmic();
        spectrum(p.add_float("gamma", &sea.gamma, 1, 10, "JONSWAP peak enhancement"));
        spectrum(p.add_choice("energy", &sea.energy, {"fit", "growth_law"},
                              "JONSWAP's alpha: the fit's (heights ~30 % above observed seas) or scaled to the "
                              "growth law E g^2/U^4 = 1.6e-7 g F/U^2"));
        spectrum(p.add_float("spread", &sea.spread, 0, 1, "fraction of the energy spread evenly over all directions"));
        spectrum(p.add_float("swell", &sea.swell, 0, 1, "narrows the spreading around the wind: long-crested swell"));
        spectrum(p.add_float("swell_height", &sea.swell_height, 0, 15,
                             "significant height of a swell added to the wind sea, metres (0: none)"));
        spectrum(p.add_float("swell_period", &sea.swell_period, 4, 25, "the swell's peak period, seconds"));
        spectrum(p.add_float("swell_direction", &sea.swell_direction, 0, 360,
                             "direction the swell travels, degrees (0 = +x, 90 = +z)"));
        spectrum(p.add_float("swell_spreading", &sea.swell_spreading, 1, 200,
                             "s of the swell's cos^2s spreading: larger is longer-crested"))
            .logarithmic();
        spectrum(p.add_float("depth", &sea.depth, 1, 10000, "water depth, metres (finite-depth dispersion)"))
            .logarithmic();
        spectrum(p.add_bool("tma", &sea.tma, "TMA: attenuate the spectrum in shallow water"));
        spectrum(p.add_float("patch_size", &sea.patch_size, 10, 5000, "side of the simulated tile, metres (it repeats)"))
            .logarithmic();
        spectrum(p.add_value_choice("resolution", &sea.resolution, {64, 128, 256, 512},
                              "modes per side of the tile (a power of two)"));
        spectrum(p.add_int("seed", &sea.seed, 0, 1000000, "seed of the random amplitudes"));
        spectrum(p.add_float("amplitude_scale", &sea.amplitude_scale, 0, 10, "height scale; 1 = physical metres"));
        spectrum(p.add_float("low_cutoff", &sea.low_cutoff, 0, 100, "remove waves with |k| below, rad/m"));
        spectrum(p.add_float("high_cutoff", &sea.high_cutoff, 0, 1000, "remove waves with |k| above, rad/m"))
            .logarithmic();
        p.add_float("choppiness", &choppiness, 0, 3, "lambda: horizontal displacement scale (sharper crests)")
            .in_group("spectrum");
    }

    const SpectrumParams& spectrum() const { return sea; }
};

}  // namespace step05
