// Chapter 5.3 on the CPU: foam where the surface folds, kept in a texture, fading with time.
//
// The Jacobian J of the horizontal displacement tells how the water's surface is squeezed: J = 1
// at rest, J < 1 where crests sharpen, J < 0 where the surface folds over itself (a breaking
// wave). At each texel the foam f obeys
//     df/dt = q - r f,    q = injection * max(0, threshold - J),  r = decay_rate
// and each frame integrates it exactly over dt, with J held through the frame:
//     f <- f e^{-r dt} + q (1 - e^{-r dt}) / r      (q dt when r = 0),  clamped to [0, 1]
// So for a J that holds still, 10 frames of 0.1 s make exactly the foam of 100 frames of 0.01 s:
// the picture does not depend on the frame rate. (The explicit step f e^{-r dt} + q dt, exact in
// its decay only, made 7 % more foam at 6 frames a second than at 60.) foam.comp does the same on
// the GPU, through foam_step.glsl.
//
// J is the Jacobian of the rendered surface, the sum of the cascades: a fold made by two
// cascades together foams, and view=foam agrees with view=jacobian. The cascades' tiles never
// line up, so the sum has no tile of its own: the foam is kept in world space, in a clipmap of
// windows that follow the camera (shaders/foam_map.glsl explains the addressing).
#pragma once

#include "common/gl.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/texel_window.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace step06 {

struct FoamSettings {
    // J below which foam appears (the bias). One value for every sea: with it the whitecap
    // coverage follows the wind as observed (README, "How much foam"; tests/physics_check whitecaps).
    double threshold = 0.75;
    double injection = 8;     // foam per second per unit of (threshold - J)
    double decay_rate = 0.8;  // 1/s: foam fades as exp(-decay_rate t)
    // The residual foam a storm leaves in streaks (foam_pattern.hpp's foam_streak_share): fed by the
    // same breaking, it fades as exp(-streak_decay t).
    double streak_decay = 0.1;  // 1/s
};

// A new foam texel starts where injection and decay would balance for the current J, so the
// first frame already has foam on the crests (a fixed clock, dt = 0, would otherwise never grow
// any). The decay rate is floored at 0.1/s so that a texel without decay does not start at 1.
inline double foam_steady_state(double jacobian, const FoamSettings& s) {
    return std::clamp(s.injection * std::max(0.0, s.threshold - jacobian) / std::max(s.decay_rate, 0.1), 0.0, 1.0);
}

// One frame of dt seconds, exact for a J that holds through it (the header's formula). The clamp
// commutes with the exact solution (it moves monotonically towards q / r), so it costs nothing.
inline double foam_step(double foam, double jacobian, double dt, const FoamSettings& s) {
    const double q = s.injection * std::max(0.0, s.threshold - jacobian);
    const double x = s.decay_rate * dt;
    const double grown = x > 0 ? q * -std::expm1(-x) / s.decay_rate : q * dt;
    return std::clamp(foam * std::exp(-x) + grown, 0.0, 1.0);
}

// The residual foam's step: foam_step's exact solution, fed by `share` of the whitecaps' breaking
// (foam_streak_share) and fading at streak_decay.
inline double residual_foam_step(double residual, double jacobian, double dt, const FoamSettings& s, double share) {
    FoamSettings residual_settings = s;
    residual_settings.injection = share * s.injection;
    residual_settings.decay_rate = s.streak_decay;
    return foam_step(residual, jacobian, dt, residual_settings);
}

// The clipmap: level l is N x N texels over kFoamExtent0 * 4^l metres (64 m, 256 m, 1024 m).
constexpr int kFoamLevels = 3;  // FOAM_LEVELS in the shaders
constexpr double kFoamExtent0 = 64;
constexpr double kFoamLevelRatio = 4;
// The residual foam of the streaks is kept on every level, beside the whitecaps' foam (the
// texture's second channel): the renderer reads both in one fetch. Before issue 23 it was kept
// on the 256 m level only, in a texture of its own, and read with a fetch of its own; the tests
// still look at that level.
constexpr int kResidualFoamLevel = 1;
inline double foam_extent(int level) { return kFoamExtent0 * std::pow(kFoamLevelRatio, level); }

// A level's window (texel_window.hpp): it moves in whole texels.
using FoamWindow = TexelWindow;
// The window of `level` around `centre` (x, z): it moves in whole texels.
FoamWindow foam_window(int level, int n, glm::dvec2 centre);
// Where a level's window is centred: ahead of the camera by 30 % of its side along the view's
// heading, so that the coarse levels cover the sea the camera looks at rather than behind it.
glm::dvec2 foam_window_centre(int level, glm::dvec2 eye_xz, glm::dvec2 forward_xz);
// How much each level's foam counts at p (x, z): the finest level that holds p, faded into the next
// over the outer tenth of its window, nothing beyond the largest. The renderer's foam_at
// (cascades_visible.glsl) fetches at most two levels; this is the sum over all three it must equal.
std::array<double, kFoamLevels> foam_level_weights(glm::dvec2 p, const std::array<FoamWindow, kFoamLevels>& windows);

// The GPU side: one rg32f layer per clipmap level (whitecaps' foam, residual foam), updated by
// foam.comp from the summed surface.
class FoamSimulation {
public:
    // Makes the bubble pattern texture (foam_pattern.hpp) once.
    explicit FoamSimulation(ocean::ProgramFactory programs);

    // A new texture (all zero) when the resolution changes; the next update then starts from the
    // steady state (foam_steady_state).
    void resize(int n);
    void fill(float value);  // every texel (tests)
    // One step of dt seconds around the camera (eye and view direction projected on x, z).
    void update(const step05::OceanSimulation& ocean, const CascadeView& cascades, glm::dvec2 eye_xz,
                glm::dvec2 forward_xz, double dt, const FoamSettings& settings);
    // The windows and the texture, for the renderer (foam_map.glsl's uniforms) and --export.
    void bind(const ocean::ShaderProgram& program, int unit) const;
    // The bubble pattern (u_foam_pattern, R8, mipmapped, repeating), the metres one tile of it
    // covers (u_foam_pattern_size), and the streaks' frame (u_streak_along, _across: world x, z to
    // the pattern's coordinates, stretched along the wind).
    void bind_pattern(const ocean::ShaderProgram& program, int unit) const;
    // The wind the streaks lie along: its heading (unit x, z: short_waves.hpp's wind_heading) and
    // speed (m/s: the share of the breaking that lingers, foam_streak_share).
    void set_wind(glm::dvec2 heading, double speed);
    // Whether there is residual foam to read (Beaufort 7 and up): the shading's STREAKS variant.
    bool streaks() const { return streak_share_ > 0; }
    static constexpr float kPatternSize = 9.0f;  // metres: about ten 1 m bubble cells a side
    const FoamWindow& window(int level) const { return windows_[std::size_t(level)]; }
    const std::array<FoamWindow, kFoamLevels>& windows() const { return windows_; }
    GLuint texture() const { return texture_.id(); }
    int resolution() const { return n_; }
    // Level `level` in the world's order: row j is z cell origin.z + j, column i x cell origin.x + i.
    std::vector<float> read_level(int level) const;
    // The residual foam of level `level`, in the same order.
    std::vector<float> read_residual(int level = kResidualFoamLevel) const;

private:
    // A level's texels (toroidal) in the world's order.
    std::vector<float> in_world_order(const std::vector<float>& stored, int level) const;
    // One channel (GL_RED the whitecaps' foam, GL_GREEN the residual) of a level, in the world's order.
    std::vector<float> read_channel(int level, GLenum channel) const;

    ocean::ProgramFactory programs_;
    ocean::Texture texture_;
    ocean::Texture pattern_;
    int n_ = 0;
    bool warm_start_ = true;
    glm::vec2 streak_along_{1.0f, 0.0f}, streak_across_{0.0f, 1.0f};
    double streak_share_ = 0;
    glm::dvec2 origin_{0.0};  // the world origin of the last update (CascadeView::origin)
    std::array<FoamWindow, kFoamLevels> windows_{};
};

}  // namespace step06
