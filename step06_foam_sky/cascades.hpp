// Chapter 5.4 on the CPU: four simulations of different sizes stacked, each owning one band of
// wavenumbers so that no wave is counted twice.
//
// Cascade c simulates a tile of side L_c (non-integer ratios, so their repeats never line up) and
// keeps the modes with b_c <= |k| < b_{c+1}. The boundaries: b_0 = 0; b_c = 2 pi * 6 / L_c (a
// cascade starts at waves six times shorter than its tile, well resolved by the previous one);
// the last band ends at the circle the last grid resolves, pi N / L_3.
#pragma once

#include "common/shader.hpp"
#include "step06_foam_sky/cascade_bands.hpp"
#include "step05_fft/ocean_params.hpp"
#include "step05_fft/spectrum.hpp"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <vector>

namespace step06 {

// kCascades, kWavesPerTileAtBoundary, Band and cascade_bands (the band split): cascade_bands.hpp.
// step06's sea, where it differs from step05's (the tests use the same): a near gale (14 m/s,
// Beaufort 7) over cascade 0's 500 m tile, choppy. Set before OceanParams::declare, so these are the defaults.
inline void use_default_sea(step05::OceanParams& params) {
    params.spectrum.patch_size = 500;
    params.spectrum.wind_speed = 14;
    params.choppiness = 1.3f;
}
// Mip levels of a 512 x 512 map (the largest resolution): the length of each cascade's row of
// u_unresolved_slope_variance (MIP_LEVELS in cascades_visible.glsl).
constexpr std::size_t kMaxMipLevels = 10;

// Tile sides from the largest, divided by 3.7, 3.3 and 3.55: no tile, nor any product of the
// ratios, is close to a whole multiple of another, so the repeats never line up.
inline std::array<double, kCascades> cascade_patch_sizes(double largest) {
    return {largest, largest / 3.7, largest / 3.7 / 3.3, largest / 3.7 / 3.3 / 3.55};
}

// The first tile must hold the spectrum's peak well: at least kPeakWavelengthsPerTile peak
// wavelengths (deep water, lambda_p = 2 pi g / omega_p^2), so that the longest waves are many
// modes, not one or two (a storm's 410 m peak in a 500 m tile repeats as a regular swell). The
// tile is patch_size, or longer when the peak needs it; the other tiles and the bands follow.
constexpr double kPeakWavelengthsPerTile = 5;
// The sea's longest peak, as an angular frequency (0 for a calm sea without swell): the wind sea's,
// or the swell's where that is longer. A swell's peak counts as much as the wind sea's.
inline double longest_peak_omega(const step05::SpectrumParams& shared) {
    double omega = step05::peak_omega_of(shared);  // 0 without wind
    if (shared.swell_height > 0) {
        const double swell = 2 * step05::kPi / shared.swell_period;
        omega = omega > 0 ? std::min(omega, swell) : swell;
    }
    return omega;
}
inline double largest_tile(const step05::SpectrumParams& shared) {
    const double omega = longest_peak_omega(shared);
    const double peak_wavelength = omega > 0 ? 2 * step05::kPi * step05::kGravity / (omega * omega) : 0;
    return std::max(shared.patch_size, kPeakWavelengthsPerTile * peak_wavelength);
}
inline std::array<double, kCascades> cascade_patch_sizes(const step05::SpectrumParams& shared) {
    return cascade_patch_sizes(largest_tile(shared));
}

// The spectrum parameters of each cascade: the shared ones, with its tile, band and seed.
inline std::array<step05::SpectrumParams, kCascades> cascade_spectra(const step05::SpectrumParams& shared) {
    const auto sizes = cascade_patch_sizes(shared);
    const auto bands = cascade_bands(sizes, shared.resolution);
    std::array<step05::SpectrumParams, kCascades> out;
    for (int c = 0; c < kCascades; ++c) {
        auto& p = out[std::size_t(c)];
        p = shared;
        p.patch_size = sizes[std::size_t(c)];
        p.low_cutoff = std::max(bands[std::size_t(c)].low, shared.low_cutoff);
        p.high_cutoff = std::min(bands[std::size_t(c)].high, shared.high_cutoff);
        p.seed = shared.seed * 4 + std::uint64_t(c);
    }
    return out;
}

// The shaders' positions are relative to a world origin near the camera (x, z), so that they stay
// small wherever the camera is: 1000 km out, float's steps are 6 cm, and a tile's phase p / L in
// float is off by as much. The origin moves in steps of kOriginStep metres, a multiple of every
// foam window's side (foam.hpp), so the foam's addressing does not change when it moves.
constexpr double kOriginStep = 4096;
inline glm::dvec2 world_origin_near(glm::dvec2 eye_xz) { return glm::round(eye_xz / kOriginStep) * kOriginStep; }

// What every pass that reads the summed surface (the renderer, foam.frag, --export) needs of the
// cascades besides their maps: each tile's side, which cascades are drawn, and where the world's
// origin is (cascades.glsl).
struct CascadeView {
    std::array<float, kCascades> patch_sizes{};
    std::array<bool, kCascades> enabled{true, true, true, true};
    glm::dvec2 origin{0.0};  // metres (x, z): the shaders' positions are relative to it (place_origin)
    std::vector<glm::vec2> tile_phases = std::vector<glm::vec2>(kCascades, glm::vec2(0.0f));

    // Puts the origin at `world_origin` (after patch_sizes are set), and each tile's phase there,
    // fract(origin / L), reduced in double once, so the shaders add it to p / L of a small p.
    void place_origin(glm::dvec2 world_origin) {
        origin = world_origin;
        for (int c = 0; c < kCascades; ++c) {
            const glm::dvec2 tiles = origin / double(patch_sizes[std::size_t(c)]);
            tile_phases[std::size_t(c)] = glm::vec2(tiles - glm::floor(tiles));
        }
    }

    // u_patch_sizes, u_tile_phases and u_cascade_enabled of `program`.
    void upload(const ocean::ShaderProgram& program) const {
        program.set("u_patch_sizes", std::vector<float>(patch_sizes.begin(), patch_sizes.end()));
        program.set("u_tile_phases", tile_phases);
        for (int c = 0; c < kCascades; ++c)
            program.set("u_cascade_enabled[" + std::to_string(c) + "]", int(enabled[std::size_t(c)]));
    }
};

}  // namespace step06
