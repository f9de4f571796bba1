// The parameters of chapter 1.2.2's sea, declared once for every program that draws it (step02's,
// and any that lights the same waves).
#pragma once

#include "common/app.hpp"
#include "step01_sine2d/wave_params.hpp"
#include "step02_sine3d/wave_uniforms.hpp"

#include <array>
#include <cmath>
#include <string>

namespace step02 {

class WaveParams {
public:
    void declare(ocean::ParamRegistry& p) {
        p.add_int("wave_count", &count_, 1, kMaxWaves, "number of waves in the sum");
        p.add_float("amplitude", &amplitude_, 0, 10, "scale applied to every wave's amplitude");
        for (int i = 0; i < kMaxWaves; ++i) {
            // Defaults: a long swell and shorter waves turning away from it, deep-water speeds.
            const float wavelength = 18.0f * std::pow(0.68f, float(i));
            auto visible = [this, i] { return i < count_; };
            directions_[i] = std::fmod(20.0f + 67.0f * float(i), 360.0f);
            p.add_float("wave" + std::to_string(i) + "_direction", &directions_[i], 0, 360,
                        "angle of the direction d in the x-z plane, degrees (0 = +x, 90 = +z); crests travel along +d")
                .in_group("wave " + std::to_string(i)).visible_if(visible);
            waves_[i] = {wavelength, 0.055f * wavelength, std::sqrt(9.81f * wavelength / 6.2831853f)};
            step01::declare_wave(p, i, waves_[i], {200, 10, 30, "crest speed, metres per second (positive: along +d)"},
                                 visible);
        }
    }

    std::vector<DirectionalWave> waves() const {
        std::vector<DirectionalWave> out;
        for (int i = 0; i < count_; ++i)
            out.push_back({directions_[i], waves_[i].wavelength, double(amplitude_) * waves_[i].amplitude,
                           waves_[i].speed});
        return out;
    }

    // The highest crest the sum can reach: colour ramps use it to span trough to crest.
    double height_extent() const {
        double extent = 0;
        for (const auto& wave : waves()) extent += std::abs(wave.amplitude);
        return extent;
    }

private:
    int count_ = 4;
    float amplitude_ = 1;
    std::array<step01::WaveSliders, kMaxWaves> waves_{};
    std::array<float, kMaxWaves> directions_{};  // degrees
};

}  // namespace step02
