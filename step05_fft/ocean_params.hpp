// The parameters of chapter 4's spectrum, declared once for every step that simulates it
// (step05, and step06's cascades), with the names the README and presets use.
#pragma once

#include "common/params.hpp"
#include "step05_fft/spectrum.hpp"

#include <array>
#include <string>

namespace step05 {

constexpr std::array<int, 4> kResolutions{64, 128, 256, 512};

class OceanParams {
public:
    void declare(ocean::ParamRegistry& p, float default_patch_size = 250, int default_resolution_index = 2,
                 float default_wind_speed = 9, float default_choppiness = 1) {
        p.add_choice("model", &model_, 0, {"jonswap", "phillips"},
                     "spectrum: JONSWAP (fetch-limited wind sea) or Phillips").in_group("spectrum");
        p.add_float("wind_speed", &wind_speed_, default_wind_speed, 0, 50, "wind speed at 10 m, m/s (0: a flat sea)")
            .in_group("spectrum");
        p.add_float("wind_direction", &wind_direction_, 30, 0, 360,
                    "direction the wind blows towards, degrees (0 = +x, 90 = +z)").in_group("spectrum");
        p.add_float("fetch", &fetch_, 100000, 1000, 5000000, "open water upwind, metres (JONSWAP)")
            .in_group("spectrum").logarithmic();
        p.add_float("gamma", &gamma_, 3.3f, 1, 10, "JONSWAP peak enhancement").in_group("spectrum");
        p.add_choice("energy", &energy_, 0, {"fit", "growth_law"},
                     "JONSWAP's alpha: the fit's (heights ~30 % above observed seas) or scaled to the growth "
                     "law E g^2/U^4 = 1.6e-7 g F/U^2").in_group("spectrum");
        p.add_float("spread", &spread_, 0.2f, 0, 1,
                    "fraction of the energy spread evenly over all directions").in_group("spectrum");
        p.add_float("swell", &swell_, 0, 0, 1, "narrows the spreading around the wind: long-crested swell")
            .in_group("spectrum");
        p.add_float("depth", &depth_, 500, 1, 10000, "water depth, metres (finite-depth dispersion)")
            .in_group("spectrum").logarithmic();
        p.add_bool("tma", &tma_, false, "TMA: attenuate the spectrum in shallow water").in_group("spectrum");
        p.add_float("patch_size", &patch_size_, default_patch_size, 10, 5000,
                    "side of the simulated tile, metres (it repeats)").in_group("spectrum").logarithmic();
        p.add_choice("resolution", &resolution_index_, default_resolution_index, {"64", "128", "256", "512"},
                     "modes per side of the tile (a power of two)").in_group("spectrum");
        p.add_int("seed", &seed_, 1, 0, 1000000, "seed of the random amplitudes").in_group("spectrum");
        p.add_float("amplitude_scale", &amplitude_scale_, 1, 0, 10, "height scale; 1 = physical metres")
            .in_group("spectrum");
        p.add_float("low_cutoff", &low_cutoff_, 0, 0, 100, "remove waves with |k| below, rad/m")
            .in_group("spectrum");
        p.add_float("high_cutoff", &high_cutoff_, 1000, 0, 1000, "remove waves with |k| above, rad/m")
            .in_group("spectrum").logarithmic();
        p.add_float("choppiness", &choppiness_, default_choppiness, 0, 3, "lambda: horizontal displacement scale (sharper crests)")
            .in_group("spectrum");
    }

    SpectrumParams spectrum() const {
        SpectrumParams s;
        s.model = SpectrumModel(model_);
        s.wind_speed = wind_speed_;
        s.wind_direction = wind_direction_;
        s.fetch = fetch_;
        s.gamma = gamma_;
        s.energy = JonswapEnergy(energy_);
        s.spread = spread_;
        s.swell = swell_;
        s.depth = depth_;
        s.tma = tma_;
        s.patch_size = patch_size_;
        s.resolution = kResolutions[std::size_t(resolution_index_)];
        s.seed = std::uint64_t(seed_);
        s.amplitude_scale = amplitude_scale_;
        s.low_cutoff = low_cutoff_;
        s.high_cutoff = high_cutoff_;
        return s;
    }

    float choppiness() const { return choppiness_; }

private:
    int model_ = 0, energy_ = 0, resolution_index_ = 2, seed_ = 1;
    float wind_speed_ = 9, wind_direction_ = 30, fetch_ = 100000, gamma_ = 3.3f, spread_ = 0.2f, swell_ = 0;
    float depth_ = 500, patch_size_ = 250, amplitude_scale_ = 1, low_cutoff_ = 0, high_cutoff_ = 1000;
    float choppiness_ = 1;
    bool tma_ = false;
};

}  // namespace step05
