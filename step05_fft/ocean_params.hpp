// The parameters of chapter 4's spectrum, declared once for every program that simulates it
// (step05's, and any that splits it into cascades), with the names the README and presets use. Each one is bound
// to the SpectrumParams field the math reads, so there is nothing to copy: the defaults are the
// struct's own (a step that wants another sea sets the fields before declare()). Every one but
// choppiness bumps `changes`: the step makes h0 again.
#pragma once

#include "common/params.hpp"
#include "step05_fft/spectrum.hpp"

namespace step05 {

class OceanParams {
public:
    SpectrumParams spectrum;  // the sea h0 is made from
    float choppiness = 1;  // lambda: not in the spectrum (changing it makes no new h0)
    // Bumped by every spectrum parameter: h0 needs recomputing when it moved.
    ocean::Generation changes;

    void declare(ocean::ParamRegistry& p) {
        {
            const auto spectrum_group = p.group("spectrum", &changes);
            p.add_choice("model", &spectrum.model, {"jonswap", "phillips"},
                    "spectrum: JONSWAP (fetch-limited wind sea) or Phillips");
            p.add_float("wind_speed", &spectrum.wind_speed, 0, 50, "wind speed at 10 m, m/s (0: a flat sea)");
            p.add_float("wind_direction", &spectrum.wind_direction, 0, 360,
                    "direction the wind blows towards, degrees (0 = +x, 90 = +z)");
            p.add_float("fetch", &spectrum.fetch, 1000, 5000000, "open water upwind, metres (JONSWAP)").logarithmic();
            p.add_float("gamma", &spectrum.gamma, 1, 10, "JONSWAP peak enhancement");
            p.add_choice("energy", &spectrum.energy, {"fit", "growth_law"},
                    "JONSWAP's alpha: the fit's (heights ~30 % above observed seas) or scaled to the "
                    "growth law E g^2/U^4 = 1.6e-7 g F/U^2");
            p.add_float("spread", &spectrum.spread, 0, 1, "fraction of the energy spread evenly over all directions");
            p.add_float("swell", &spectrum.swell, 0, 1, "narrows the spreading around the wind: long-crested swell");
            p.add_choice("spreading", &spectrum.spreading, {"hasselmann", "donelan_banner"},
                    "the wind sea's directions: Hasselmann's cos^2s(theta/2) or Donelan-Banner's sech^2(beta theta)");
            p.add_float("swell_height", &spectrum.swell_height, 0, 15,
                    "significant height of a swell added to the wind sea, metres (0: none)");
            p.add_float("swell_period", &spectrum.swell_period, 4, 25, "the swell's peak period, seconds");
            p.add_float("swell_direction", &spectrum.swell_direction, 0, 360,
                    "direction the swell travels, degrees (0 = +x, 90 = +z)");
            p.add_float("swell_spreading", &spectrum.swell_spreading, 1, 200,
                    "s of the swell's cos^2s spreading: larger is longer-crested").logarithmic();
            p.add_float("depth", &spectrum.depth, 1, 10000, "water depth, metres (finite-depth dispersion)")
                .logarithmic();
            p.add_bool("tma", &spectrum.tma, "TMA: attenuate the spectrum in shallow water");
            p.add_float("patch_size", &spectrum.patch_size, 10, 5000, "side of the simulated tile, metres (it repeats)")
                .logarithmic();
            p.add_value_choice("resolution", &spectrum.resolution, {64, 128, 256, 512},
                    "modes per side of the tile (a power of two)");
            p.add_int("seed", &spectrum.seed, 0, 1000000, "seed of the random amplitudes");
            p.add_float("amplitude_scale", &spectrum.amplitude_scale, 0, 10, "height scale; 1 = physical metres");
            p.add_float("low_cutoff", &spectrum.low_cutoff, 0, 100, "remove waves with |k| below, rad/m");
            p.add_float("high_cutoff", &spectrum.high_cutoff, 0, 1000, "remove waves with |k| above, rad/m")
                .logarithmic();
        }
        p.add_float("choppiness", &choppiness, 0, 3, "lambda: horizontal displacement scale (sharper crests)")
            .in_group("spectrum");
    }
};

}  // namespace step05
