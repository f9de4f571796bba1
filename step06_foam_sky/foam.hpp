// Chapter 5.3 on the CPU: foam where the surface folds, kept in a texture, fading with time.
//
// The Jacobian J of the horizontal displacement tells how the water's surface is squeezed: J = 1
// at rest, J < 1 where crests sharpen, J < 0 where the surface folds over itself (a breaking
// wave). Each frame, at each texel:
//     foam <- foam * exp(-decay_rate * dt) + injection * max(0, threshold - J) * dt,  clamped to [0, 1]
// The decay factor is exact for any dt (exp(-r dt)^n = exp(-r t)), and the injection is a rate
// (scaled by dt), so foam does not depend on the frame rate. foam.comp does the same on the GPU.
#pragma once

#include "common/gl.hpp"
#include "step05_fft/gpu_ocean.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace step06 {

struct FoamSettings {
    double threshold = 0.8;   // J below which foam appears (the bias)
    double injection = 8;     // foam per second per unit of (threshold - J)
    double decay_rate = 0.8;  // 1/s: foam fades as exp(-decay_rate t)
};

// A new foam texture starts where injection and decay would balance for the current J, so the
// first frame already has foam on the crests (a fixed clock, dt = 0, would otherwise never grow any).
inline double foam_steady_state(double jacobian, const FoamSettings& s) {
    return std::clamp(s.injection * std::max(0.0, s.threshold - jacobian) / std::max(s.decay_rate, 0.1), 0.0, 1.0);
}

inline double foam_step(double foam, double jacobian, double dt, const FoamSettings& s) {
    const double added = s.injection * std::max(0.0, s.threshold - jacobian) * dt;
    return std::clamp(foam * std::exp(-s.decay_rate * dt) + added, 0.0, 1.0);
}


// The GPU side: one r32f layer per cascade, updated by foam.comp from the cascade's Jacobian.
class FoamSimulation {
public:
    explicit FoamSimulation(ocean::ProgramFactory programs) : programs_(std::move(programs)) {}

    // A new texture (all zero) when the resolution or cascade count changes; the next update
    // then starts from the steady state (foam_steady_state).
    void resize(int n, int layers);
    void fill(float value);  // every texel (tests)
    // One step of dt seconds. `weights`: each cascade's share of the injection.
    void update(const step05::GpuOcean& ocean, double dt, const FoamSettings& settings,
                const std::array<float, 4>& weights);
    GLuint texture() const { return texture_.id(); }
    std::vector<float> read_layer(int layer) const;

private:
    ocean::ProgramFactory programs_;
    ocean::Texture texture_;
    int n_ = 0, layers_ = 0;
    bool warm_start_ = true;
};

}  // namespace step06
