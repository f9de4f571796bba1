#include "step06_foam_sky/cascade_bands.hpp"

#include "common/constants.hpp"

#include <cstddef>

namespace step06 {

// Each boundary b_c (c > 0) ends band c - 1 and starts band c: one number for both, so no wave
// falls between two bands or into both.
std::array<Band, kCascades> cascade_bands(const std::array<double, kCascades>& patch_sizes, int resolution) {
    std::array<Band, kCascades> bands{};
    for (int c = 0; c < kCascades; ++c) {
        bands[c].low = c == 0 ? 0.0 : 2 * ocean::kPi * kWavesPerTileAtBoundary / patch_sizes[std::size_t(c)];
        if (c > 0) bands[std::size_t(c - 1)].high = bands[std::size_t(c)].low;
    }
    bands[kCascades - 1].high = ocean::kPi * resolution / patch_sizes[kCascades - 1];
    return bands;
}

}  // namespace step06
