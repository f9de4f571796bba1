// Chapter 5.4's band split (cascades.hpp builds each cascade's spectrum with it): which wavenumbers
// each of the four cascades keeps, so that every wave of the sea is simulated by exactly one of them.
// Its own file, with no GL and nothing of step05's: exercise 7 (./ocean exercise step06_foam_sky 7)
// empties cascade_bands() in a copy of cascade_bands.cpp, and its check compiles that copy alone.
#pragma once

#include <array>

namespace step06 {

constexpr int kCascades = 4;
// A cascade's band starts where its tile holds this many waves: well resolved by the cascade before.
constexpr double kWavesPerTileAtBoundary = 6;

struct Band {
    double low, high;  // rad/m, low <= |k| < high
};

// Cascade c, of tile side patch_sizes[c] (largest first) on a resolution x resolution grid, keeps
// the modes with low <= |k| < high of its band: cascade 0 from k = 0, each later one from where its
// tile holds kWavesPerTileAtBoundary waves, the last up to the circle the last grid resolves. The
// bands tile [0, that circle) without a gap or an overlap (sea.md, section 1; how_we_know.md has
// the bounds).
std::array<Band, kCascades> cascade_bands(const std::array<double, kCascades>& patch_sizes, int resolution);

}  // namespace step06
