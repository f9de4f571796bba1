// The parameters of chapter 1.2.2's sea, declared once for every step that draws it (step02,
// and step03 which lights the same waves): the waves, the grid and the default camera.
#pragma once

#include "common/app.hpp"
#include "common/grid.hpp"
#include "step02_sine3d/wave_uniforms.hpp"

#include <array>
#include <cmath>
#include <string>

namespace step02 {

// Where steps 02-04 look from, so their screenshots line up.
struct CameraView { glm::vec3 target; float distance, yaw_deg, pitch_deg; };
constexpr CameraView kDefaultCamera{{0, 0, 0}, 70, 35, 28};

class WaveParams {
public:
    void declare(ocean::ParamRegistry& p) {
        p.add_int("wave_count", &count_, 4, 1, kMaxWaves, "number of waves in the sum");
        p.add_float("amplitude", &amplitude_, 1, 0, 10, "scale applied to every wave's amplitude");
        for (int i = 0; i < kMaxWaves; ++i) {
            const std::string prefix = "wave" + std::to_string(i) + "_";
            const std::string group = "wave " + std::to_string(i);
            // Defaults: a long swell and shorter waves turning away from it, deep-water speeds.
            const float wavelength = 18.0f * std::pow(0.68f, float(i));
            auto visible = [this, i] { return i < count_; };
            p.add_float(prefix + "direction", &waves_[i].direction, std::fmod(20.0f + 67.0f * float(i), 360.0f), 0,
                        360, "angle of the direction d in the x-z plane, degrees (0 = +x, 90 = +z); crests travel along +d")
                .in_group(group).visible_if(visible);
            p.add_float(prefix + "wavelength", &waves_[i].wavelength, wavelength, 0.1f, 200,
                        "distance between crests, metres").in_group(group).visible_if(visible).logarithmic();
            p.add_float(prefix + "amplitude", &waves_[i].amplitude, 0.055f * wavelength, 0, 10,
                        "height of a crest above rest, metres").in_group(group).visible_if(visible);
            p.add_float(prefix + "speed", &waves_[i].speed, std::sqrt(9.81f * wavelength / 6.2831853f), -30, 30,
                        "crest speed, metres per second (positive: along +d)")
                .in_group(group).visible_if(visible);
        }
    }

    std::vector<DirectionalWave> waves() const {
        std::vector<DirectionalWave> out;
        for (int i = 0; i < count_; ++i)
            out.push_back({waves_[i].direction, waves_[i].wavelength, double(amplitude_) * waves_[i].amplitude,
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
    struct Wave { float direction, wavelength, amplitude, speed; };
    int count_ = 4;
    float amplitude_ = 1;
    std::array<Wave, kMaxWaves> waves_{};
};

class GridParams {
public:
    void declare(ocean::ParamRegistry& p, float default_size = 80, int default_quads = 160) {
        p.add_float("plane_size", &plane_size_, default_size, 1, 5000, "side of the square plane, metres")
            .in_group("grid");
        p.add_int("x_quads", &x_quads_, default_quads, 1, 2048, "grid cells along x (vertices: x_quads + 1)")
            .in_group("grid");
        p.add_int("z_quads", &z_quads_, default_quads, 1, 2048, "grid cells along z (vertices: z_quads + 1)")
            .in_group("grid");
    }

    // Rebuilds the mesh only when its size or resolution changed.
    void update(ocean::GridMesh& grid) {
        const std::array<float, 3> wanted{plane_size_, float(x_quads_), float(z_quads_)};
        if (wanted == built_for_) return;
        grid.build({plane_size_, plane_size_}, x_quads_, z_quads_);
        built_for_ = wanted;
    }

    int triangle_count() const { return 2 * x_quads_ * z_quads_; }

private:
    float plane_size_ = 80;
    int x_quads_ = 160, z_quads_ = 160;
    std::array<float, 3> built_for_{-1, -1, -1};
};

}  // namespace step02
