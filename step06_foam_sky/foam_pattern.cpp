#include "step06_foam_sky/foam_pattern.hpp"

#include "common/random.hpp"  // uniform01: splitmix64, the same pattern on every machine

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
        point_x[i] = ocean::uniform01(state);
        point_y[i] = ocean::uniform01(state);
        shade[i] = ocean::uniform01(state);
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

std::vector<float> foam_noise(const FoamPatternSettings& s) {
    if (s.size < 4 || s.noise_cells < 2 || 2 * s.noise_cells > s.size) throw std::invalid_argument("foam noise: bad size or cell count");
    std::uint64_t state = s.seed ^ 0x9e3779b97f4a7c15ull;  // not the cells' sequence
    std::vector<double> sum(std::size_t(s.size) * s.size, 0.0);
    for (int octave = 0; octave < 2; ++octave) {
        const int cells = s.noise_cells << octave;
        const double weight = octave == 0 ? 1.0 : 0.5;
        std::vector<double> lattice(std::size_t(cells) * cells);
        for (double& v : lattice) v = ocean::uniform01(state);
        const auto at = [&](int i, int j) { return lattice[std::size_t(((j % cells) + cells) % cells) * cells + ((i % cells) + cells) % cells]; };
        for (int y = 0; y < s.size; ++y)
            for (int x = 0; x < s.size; ++x) {
                const double u = (x + 0.5) * cells / s.size, v = (y + 0.5) * cells / s.size;
                const int i = int(std::floor(u)), j = int(std::floor(v));
                const double fu = u - i, fv = v - j;
                const double wu = fu * fu * (3 - 2 * fu), wv = fv * fv * (3 - 2 * fv);  // no kinks at the lattice
                const double value = (1 - wv) * ((1 - wu) * at(i, j) + wu * at(i + 1, j)) + wv * ((1 - wu) * at(i, j + 1) + wu * at(i + 1, j + 1));
                sum[std::size_t(y) * s.size + x] += weight * value;
            }
    }
    const auto [low, high] = std::minmax_element(sum.begin(), sum.end());
    const double lo = *low, span = std::max(*high - *low, 1e-12);
    std::vector<float> out(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) out[i] = float((sum[i] - lo) / span);
    return out;
}

std::vector<std::uint8_t> to_r8(const std::vector<float>& pattern) {
    std::vector<std::uint8_t> bytes(pattern.size());
    for (std::size_t i = 0; i < pattern.size(); ++i)
        bytes[i] = std::uint8_t(std::lround(std::clamp(double(pattern[i]), 0.0, 1.0) * 255.0));
    return bytes;
}

std::vector<std::uint8_t> foam_pattern_texture(const FoamPatternSettings& settings) {
    FoamPatternSettings other = settings;
    other.seed = settings.seed + 1;
    const std::vector<float> cells = foam_pattern(settings), noise = foam_noise(settings), noise2 = foam_noise(other);
    std::vector<float> squares(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) squares[i] = cells[i] * cells[i];
    const std::vector<std::uint8_t> r = to_r8(cells), g = to_r8(noise), b = to_r8(squares), a = to_r8(noise2);
    std::vector<std::uint8_t> rgba(4 * cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) rgba[4 * i] = r[i], rgba[4 * i + 1] = g[i], rgba[4 * i + 2] = b[i], rgba[4 * i + 3] = a[i];
    return rgba;
}

std::vector<std::uint8_t> streak_lines_texture(const FoamPatternSettings& settings) {
    std::vector<float> lines = foam_pattern(settings);
    for (float& value : lines) value = float(streak_line(value));
    const std::vector<std::uint8_t> r = to_r8(lines);
    std::vector<std::uint8_t> rgba(4 * lines.size(), 0);
    for (std::size_t i = 0; i < lines.size(); ++i) rgba[4 * i] = r[i];
    return rgba;
}

}  // namespace step06
