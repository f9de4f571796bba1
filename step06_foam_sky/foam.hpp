// Chapter 5.3 on the CPU: foam where the surface folds, kept in a texture, fading with time, in
// the two stages photographs of the sea separate (Monahan and Lu 1990).
//
// The Jacobian J of the horizontal displacement tells how the water's surface is squeezed: J = 1
// at rest, J < 1 where crests sharpen, J < 0 where the surface folds over itself (a breaking
// wave). At each texel two amounts of foam are kept:
//   - a, the active whitecap (stage A): made where the surface squeezes, bright, short-lived;
//   - b, the residual foam it leaves (stage B): the whitecap's foam once it stops breaking, a
//     thinning raft of bubbles that lasts several times longer.
// Both come from one breaking, remembered by two clocks:
//     da/dt = q - r_a a,          q = injection * max(0, threshold - J)
//     df/dt = q - r_b f           (f: the foam as a whole, r_b < r_a)
// each held at or below 1 (a texel cannot be more than covered), and the residual foam is what
// the slow clock remembers and the fast one has forgotten: b = f - a, between 0 and 1 - a (with
// the same q, the slower decay stays above). When a crest stops breaking its active foam is gone
// in a second or two, and the residual it leaves peaks, then fades as e^{-r_b t}.
// Each frame integrates both exactly over dt, with J held through the frame (the same step at two
// rates): the same foam at any frame rate. foam.frag does the same on the GPU, through
// foam_step.glsl. Deriving that step is exercise 3 (foam.md gives the method); foam_step below is
// its answer.
//
// J is the Jacobian of the rendered surface, the sum of the cascades: a fold made by two
// cascades together foams, and view=foam agrees with view=jacobian. The cascades' tiles never
// line up, so the sum has no tile of its own: the foam is kept in world space, in a clipmap of
// windows that follow the camera (shaders/foam_map.glsl explains the addressing). It is kept per
// rest position (the label of the water that the displacement carries around its orbit), so the
// renderer draws it where that water is: foam moves with the surface it floats on.
#pragma once

#include "common/gl.hpp"
#include "common/gl_texture.hpp"
#include "step05_fft/simulation_maps.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/texel_window.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace step06 {

class ExtraWaves;

struct FoamSettings {
    // J below which foam appears (the bias). One value for every sea: with it the whitecap
    // coverage follows the wind as observed (foam.md, "How much foam"; tests/sea_check.cpp whitecaps).
    double threshold = 0.64;
    double injection = 16;    // active foam per second per unit of (threshold - J)
    double decay_rate = 1.6;  // 1/s: r_a, the active whitecap stops breaking as exp(-r_a t)
    double residual_decay = 0.1;  // 1/s: r_b, the foam as a whole (the residual it leaves) fades as exp(-r_b t)
};

// A new foam texel starts where injection and decay would balance for the current J, so the
// first frame already has foam on the crests (a fixed clock, dt = 0, would otherwise never grow
// any). The decay rate is floored at 0.1/s so that a texel without decay does not divide by zero.
inline double foam_steady_state(double jacobian, const FoamSettings& s) {
    return std::clamp(s.injection * std::max(0.0, s.threshold - jacobian) / std::max(s.decay_rate, 0.1), 0.0, 1.0);
}

// One frame of dt seconds, exact for a J that holds through it (foam.md, section 3: its method). The clamp
// commutes with the exact solution (it moves monotonically towards q / r), so it costs nothing.
inline double foam_step(double foam, double jacobian, double dt, const FoamSettings& s) {
    const double q = s.injection * std::max(0.0, s.threshold - jacobian);
    const double x = s.decay_rate * dt;
    const double grown = x > 0 ? q * -std::expm1(-x) / s.decay_rate : q * dt;
    return std::clamp(foam * std::exp(-x) + grown, 0.0, 1.0);
}

// The foam as a whole, f: the same clock as the active foam's at the residual's rate r_b.
inline FoamSettings slow_clock(const FoamSettings& s) {
    FoamSettings slow = s;
    slow.decay_rate = s.residual_decay;
    return slow;
}
inline double whole_foam_step(double whole, double jacobian, double dt, const FoamSettings& s) {
    return foam_step(whole, jacobian, dt, slow_clock(s));
}
inline double whole_foam_steady_state(double jacobian, const FoamSettings& s) {
    return foam_steady_state(jacobian, slow_clock(s));
}
// The residual foam: what the foam as a whole holds beyond the active part (never below 0, for a
// residual rate set above the active one).
inline double residual_foam(double active, double whole) { return std::max(0.0, whole - active); }

// The clipmap: level l is N x N texels over kFoamExtent0 * 4^l metres (64 m, 256 m, 1024 m).
constexpr int kFoamLevels = 3;  // FOAM_LEVELS in the shaders
constexpr double kFoamExtent0 = 64;
constexpr double kFoamLevelRatio = 4;
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

// The GPU side: one rg32f layer per clipmap level (active foam a, foam as a whole f), updated by
// foam.frag from the summed surface.
class FoamSimulation {
public:
    // Makes the bubble pattern texture (foam_pattern.hpp) once.
    explicit FoamSimulation(ocean::ProgramFactory programs);

    // A new texture (all zero) when the resolution changes; the next update then starts from the
    // steady state (foam_steady_state).
    void resize(int n);
    void fill(float value);  // every texel (tests)
    // One step of dt seconds around the camera (eye and view direction projected on x, z), from the
    // simulation's maps (OceanSimulation::maps or FragmentSimulation::maps): foam.frag drawn into
    // each level's layer of the texture it did not write last time, reading the other. The draw
    // framebuffer, viewport, blending and program in use are put back. `extra`: waves added to the
    // cascades' (extra_waves.hpp), or none.
    void update(const step05::SimulationMaps& maps, const CascadeView& cascades, glm::dvec2 eye_xz,
                glm::dvec2 forward_xz, double dt, const FoamSettings& settings, const ExtraWaves* extra = nullptr);
    // The windows and the texture, for the renderer (foam_map.glsl's uniforms) and --export.
    void bind(const ocean::ShaderProgram& program, int unit) const;
    // The pattern texture (u_foam_pattern, RGBA8: foam_pattern_texture; mipmapped, repeating), the
    // metres one tile of it covers (u_foam_pattern_size), and the streaks' frames (u_streak_*,
    // u_meander_*, u_break_*: world x, z to the pattern's coordinates, stretched along the wind).
    void bind_pattern(const ocean::ShaderProgram& program, int unit) const;
    // The streaks' line cover (u_streak_lines, RGBA8: streak_lines_texture; mipmapped, repeating).
    void bind_streak_lines(const ocean::ShaderProgram& program, int unit) const;
    // The wind the streaks lie along: its heading (unit x, z: short_waves.hpp's wind_heading) and
    // speed (m/s: the share of the residual foam drawn as streaks, foam_streak_share).
    void set_wind(glm::dvec2 heading, double speed);
    // Whether the residual foam is combed into streaks (Beaufort 7 and up): the shading's STREAKS variant.
    // Below 5 % of their strength the streaks' cover is under 5 % of the residual's, not seen: their
    // three fetches are compiled out (force 7 begins at 13.9 m/s; they come in from 14.25 m/s).
    bool streaks() const { return streak_share_ >= 0.05; }
    static constexpr float kPatternSize = 9.0f;  // metres: about ten 1 m bubble cells a side
    const FoamWindow& window(int level) const { return windows_[std::size_t(level)]; }
    const std::array<FoamWindow, kFoamLevels>& windows() const { return windows_; }
    GLuint texture() const { return textures_[current_].id(); }  // the foam the last update made
    int resolution() const { return n_; }
    // Level `level` in the world's order: row j is z cell origin.z + j, column i x cell origin.x + i.
    std::vector<float> read_level(int level) const;
    // The foam as a whole (f) of level `level`, in the same order.
    std::vector<float> read_whole(int level = 0) const;

private:
    // A level's texels (toroidal) in the world's order.
    std::vector<float> in_world_order(const std::vector<float>& stored, int level) const;
    // One channel (0 the active foam, 1 the foam as a whole) of a level, in the world's order.
    std::vector<float> read_channel(int level, int channel) const;

    ocean::ProgramFactory programs_;
    // The foam, twice: each update reads textures_[current_] and writes the other, then swaps.
    std::array<ocean::Texture, 2> textures_;
    std::array<std::array<ocean::Framebuffer, kFoamLevels>, 2> level_targets_;  // each level's layer
    std::size_t current_ = 0;
    ocean::VertexArray no_vertices_;  // the full-screen triangle's corners come from gl_VertexID
    ocean::Texture pattern_;
    ocean::Texture streak_lines_;
    int n_ = 0;
    bool warm_start_ = true;
    glm::vec2 wind_along_{1.0f, 0.0f};  // the wind's heading (x, z): the streaks' frame follows it
    double streak_share_ = 0;
    glm::dvec2 origin_{0.0};  // the world origin of the last update (CascadeView::origin)
    std::array<FoamWindow, kFoamLevels> windows_{};
};

}  // namespace step06
