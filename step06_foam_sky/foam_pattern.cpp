#include "step06_foam_sky/foam_pattern.hpp"

#include "step04_fbm/fbm.hpp"  // uniform01: splitmix64, the same pattern on every machine

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace step06 {

std::vector<float> foam_pattern(const FoamPatternSettings& s) {
    if (s.size < 4 || s.cells < 2 || s.cells > s.size) throw std::invalid_argument("foam pattern: bad size or cell count");
    // One feature point per cell, jittered inside it; the grid wraps, so the pattern is periodic.
    const int cells = s.cells;
    std::uint64_t state = s.seed;
    std::vector<double> point_x(std::size_t(cells) * cells), point_y(point_x.size()), shade(point_x.size());
    for (std::size_t i = 0; i < point_x.size(); ++i) {
        point_x[i] = step04::uniform01(state);
        point_y[i] = step04::uniform01(state);
        shade[i] = step04::uniform01(state);
    }
    std::vector<float> out(std::size_t(s.size) * s.size);
    const double cell_per_texel = double(cells) / s.size;
    for (int y = 0; y < s.size; ++y)
        for (int x = 0; x < s.size; ++x) {
            const double u = (x + 0.5) * cell_per_texel, v = (y + 0.5) * cell_per_texel;  // in cells
            const int cx = int(std::floor(u)), cy = int(std::floor(v));
            double f1 = 1e9, f2 = 1e9, nearest_shade = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int gx = cx + dx, gy = cy + dy;
                    const std::size_t k = std::size_t(((gy % cells) + cells) % cells) * cells + ((gx % cells) + cells) % cells;
                    const double px = gx + point_x[k], py = gy + point_y[k];
                    const double d = std::hypot(u - px, v - py);
                    if (d < f1) {
                        f2 = f1;
                        f1 = d;
                        nearest_shade = shade[k];
                    } else if (d < f2) {
                        f2 = d;
                    }
                }
            // F2 - F1 is 0 on a border between two cells and about half a cell in a middle.
            const double border = std::exp(-(f2 - f1) / 0.18);
            const double value = 0.8 * border + 0.2 * nearest_shade;
            out[std::size_t(y) * s.size + x] = float(std::clamp(value, 0.0, 1.0));
        }
    return out;
}

std::vector<std::uint8_t> to_r8(const std::vector<float>& pattern) {
    std::vector<std::uint8_t> bytes(pattern.size());
    for (std::size_t i = 0; i < pattern.size(); ++i)
        bytes[i] = std::uint8_t(std::lround(std::clamp(double(pattern[i]), 0.0, 1.0) * 255.0));
    return bytes;
}

}  // namespace step06
