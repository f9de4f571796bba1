// step04's wave parameters, declared once and bound to the fields the math reads. Those that make
// new waves (count, wavelength, amplitude, gain, lacunarity, speed, seed, cascades) bump
// `changes`; the shape and the warp are read every frame and bump nothing, and neither does
// anything outside this class (the camera, the light, the grid). So a camera drag rebuilds no
// waves (Step04Params.OnlyWaveParametersRebuildTheWaves).
#pragma once

#include "common/params.hpp"
#include "step04_fbm/fbm.hpp"

namespace step04 {

class FbmParams {
public:
    // The defaults the chapter starts from (20 waves of 40 m, a0 = 1.2 m; two cascades at 0.37).
    int shape = int(Shape::ExpSine), wave_count = 20, seed = 1, cascade_count = 2;
    float base_wavelength = 40, amplitude = 1.2f, gain = 0.82f, lacunarity = 1.18f, speed_scale = 1;
    float warp = 4, cascade_ratio = 0.37f;
    ocean::Generation changes;

    // Every parameter but the shape and the warp changes the waves themselves: those bump
    // `changes` and the step rebuilds its cascades (the shape picks a compile-time variant of
    // the shaders, `#define SHAPE`; the warp is a uniform).
    void declare(ocean::ParamRegistry& p) {
        const auto fbm_group = p.group("fbm");
        p.add_choice("shape", &shape, {"sine", "exp_sine", "power_sine"},
                     "wave shape: sin(x), exp(sin(x) - 1) with sharp crests and flat troughs, or "
                     "((1 + sin(x)) / 2)^3 (GPU Gems 1's sharpened sine)");
        {
            const auto waves_group = p.group("fbm", &changes);
            p.add_int("wave_count", &wave_count, 1, kMaxWavesPerCascade, "waves in each cascade");
            p.add_float("base_wavelength", &base_wavelength, 1, 500, "wavelength of wave 0, metres").logarithmic();
            p.add_float("amplitude", &amplitude, 0, 10, "amplitude of wave 0 (a0), metres");
            p.add_float("gain", &gain, 0, 1, "amplitude ratio of neighbouring waves");
            p.add_float("lacunarity", &lacunarity, 1, 3, "frequency ratio of neighbouring waves");
            p.add_float("speed_scale", &speed_scale, 0, 5,
                        "a factor on every wave's phase rate: 1 = deep water, phi = sqrt(g w) (step01's speed is m/s)");
            p.add_int("seed", &seed, 0, 1000000, "seed of the wave directions");
        }
        p.add_float("warp", &warp, 0, 10,
                    "domain warping strength (beta): each wave pushes the next ones' input by warp * a * grad f");
        const auto cascades_group = p.group("cascades", &changes);
        p.add_int("cascade_count", &cascade_count, 1, kMaxCascades, "independent sums layered");
        p.add_float("cascade_ratio", &cascade_ratio, 0.05f, 0.95f,
                    "base wavelength and amplitude of cascade c: ratio^c times cascade 0's");
    }

    // The cascades these parameters describe.
    std::vector<Cascade> make() const {
        CascadeSettings s;
        s.wave_count = wave_count;
        s.base_wavelength = base_wavelength;
        s.base_amplitude = amplitude;
        s.gain = gain;
        s.lacunarity = lacunarity;
        s.speed_scale = speed_scale;
        s.seed = std::uint64_t(seed);
        return make_cascades(s, cascade_count, cascade_ratio);
    }
};

}  // namespace step04
