// The cascades combined once a frame around the camera (Crest's "LOD data"), the `surface=combined`
// setting. Each pixel of the cascades path reads four cascades, each with up to four anisotropic
// pieces; here a compute pass first sums the four into nested square levels centred on the camera,
// each twice the side of the one inside it and all n x n texels, and the mesh and the shading read
// one level (two where a level hands over to the next): one fetch a piece instead of four.
//
// Level k's texel is texel0 2^k, texel0 a power of two of metres no larger than the finest
// cascade's texel: every level's texel then divides kOriginStep, and the world origin moves by
// whole texels of every level. Each level's window moves with the camera in whole texels
// (texel_window.hpp), so a texel always holds the same point of the sea: nothing swims.
//
// A texel of level k holds the summed surface as a sample one texel wide sees it: cascades.glsl's
// surface_at, each cascade at the whole mip level nearest the texel (the foam's sampling), so the
// level's own mipmaps (box_mip.comp) carry on the averaging for wider footprints.
//
// A point p at reach r = max(|x - eye x|, |z - eye z|) is read from the finest level k with
// r <= kLevelReach * side_k, and blended into level k + 1 from kBlendFrom * side_k: the band keeps
// the change of level from showing as a seam, and the margin beyond kLevelReach (up to half the
// side) holds the anisotropic pieces and the window's snap to whole texels.
#pragma once

#include "common/shader.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/texel_window.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace step06 {

constexpr int kMaxCombinedLevels = 12;  // MAX_COMBINED_LEVELS in combined_surface.glsl
constexpr double kLevelReach = 0.4;     // a level serves points up to this share of its side from the camera
constexpr double kBlendFrom = 0.3;      // and hands over to the next one from this share

// The finest level's texel: the largest power of two (metres) no larger than `finest_texel`.
inline double combined_texel0(double finest_texel) { return std::exp2(std::floor(std::log2(finest_texel))); }

// The levels that hold the sea out to `reach` metres from the camera (the mesh's half side):
// level L - 1's side times kLevelReach reaches it. At least one, at most kMaxCombinedLevels: a
// mesh wider than that (patch_count and tess_patch_size at their largest: 40 km) reads the last
// level's edge beyond it, where a footprint is averaged nearly flat by the mipmaps anyway.
inline int combined_level_count(double reach, int n, double texel0) {
    const double needed = std::ceil(std::log2(std::max(reach / (kLevelReach * n * texel0), 1.0)));
    return std::clamp(int(needed) + 1, 1, kMaxCombinedLevels);
}

// Which level serves a point at `reach` from the camera, and the weight of the next level there
// (combined_surface.glsl's combined_levels_at, in double).
struct LevelChoice {
    int level;
    double next_weight;
};
inline LevelChoice combined_level_at(double reach, double side0, int levels) {
    const int level =
        std::clamp(int(std::ceil(std::log2(std::max(reach / (kLevelReach * side0), 1.0)))), 0, levels - 1);
    const double side = side0 * std::exp2(level);
    const double next = level + 1 < levels
                            ? std::clamp((reach / side - kBlendFrom) / (kLevelReach - kBlendFrom), 0.0, 1.0)
                            : 0.0;
    return {level, next};
}

// The GPU side: two RGBA16F 2D arrays (the summed displacement and slopes, a layer a level, with
// mipmaps), filled by combine.comp from the cascades' maps.
class CombinedSurface {
public:
    explicit CombinedSurface(ocean::ProgramFactory programs) : programs_(std::move(programs)) {}

    // `levels` levels of n x n (a power of two) texels, the finest of texel0 metres; new textures
    // only when one of them changed.
    void resize(int n, int levels, double texel0);
    // This frame's levels around the camera (x, z in world metres), holding cascades 0 to
    // `combined_cascades` - 1; the shaders read the others as the cascades path does.
    void update(const step05::OceanSimulation& ocean, const CascadeView& cascades, glm::dvec2 eye_xz,
                int combined_cascades = kCascades);
    // The textures on their units (texture_units.h) and combined_surface.glsl's uniforms.
    void bind(const ocean::ShaderProgram& program) const;

    int levels() const { return levels_; }
    int resolution() const { return n_; }
    const TexelWindow& window(int level) const { return windows_[std::size_t(level)]; }
    // Level `level` (mip 0), row j the z cell window(level).origin.y + j: displacement or slopes.
    std::vector<glm::vec4> read_level(int level, bool slopes) const;

private:
    ocean::ProgramFactory programs_;
    ocean::Texture displacement_, slopes_;
    int n_ = 0, levels_ = 0, combined_cascades_ = kCascades;
    double texel0_ = 0;
    glm::dvec2 origin_{0.0};  // the world origin of the last update (CascadeView::origin)
    glm::dvec2 eye_xz_{0.0};  // the camera the last update centred the levels on
    std::vector<TexelWindow> windows_;
};

}  // namespace step06
