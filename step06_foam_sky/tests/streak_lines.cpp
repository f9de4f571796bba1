// The streaks of a picture, measured (streak_lines.hpp).
#include "step06_foam_sky/tests/streak_lines.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

namespace step06_test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The median of values weighted by weights: the value the middle of the total weight falls on.
double weighted_median(std::vector<std::pair<double, double>> value_weight) {
    std::sort(value_weight.begin(), value_weight.end());
    double total = 0, sum = 0;
    for (const auto& vw : value_weight) total += vw.second;
    for (const auto& vw : value_weight)
        if ((sum += vw.second) >= 0.5 * total) return vw.first;
    return 0;
}

// The cover on a grid of the sea's mean level: kStep metres a cell, x along the wind, y across it,
// centred under the picture's middle; -1 where a cell is outside the picture or its foam cannot be
// told from water. Each cell reads the picture between the pixels' centres (bilinear).
constexpr double kStep = 0.1;
struct SeaGrid {
    int columns = 0, rows = 0;
    std::vector<double> cover;
    double at(int x, int y) const { return cover[std::size_t(y) * std::size_t(columns) + std::size_t(x)]; }
};

double bilinear(int width, int height, const std::vector<double>& cover, glm::dvec2 position) {
    const double x = position.x - 0.5, y = position.y - 0.5;
    const int i = int(std::floor(x)), j = int(std::floor(y));
    if (i < 0 || j < 0 || i + 1 >= width || j + 1 >= height) return -1;
    auto c = [&](int u, int v) { return cover[std::size_t(v) * std::size_t(width) + std::size_t(u)]; };
    const double c00 = c(i, j), c10 = c(i + 1, j), c01 = c(i, j + 1), c11 = c(i + 1, j + 1);
    if (c00 < 0 || c10 < 0 || c01 < 0 || c11 < 0) return -1;
    const double fx = x - i, fy = y - j;
    return (c00 * (1 - fx) + c10 * fx) * (1 - fy) + (c01 * (1 - fx) + c11 * fx) * fy;
}

SeaGrid on_the_sea(const ocean_test::Pinhole& camera, int width, int height, const std::vector<double>& cover,
                   glm::dvec3 along, glm::dvec3 across, double half_side) {
    const std::optional<glm::dvec3> centre = camera.ground(camera.ray_through({width / 2.0, height / 2.0}, width, height));
    if (!centre) return {};
    SeaGrid g;
    g.columns = g.rows = 2 * int(half_side / kStep);
    g.cover.assign(std::size_t(g.columns) * std::size_t(g.rows), -1);
    for (int y = 0; y < g.rows; ++y)
        for (int x = 0; x < g.columns; ++x) {
            const glm::dvec3 point = *centre + (x * kStep - half_side) * along + (y * kStep - half_side) * across;
            g.cover[std::size_t(y) * std::size_t(g.columns) + std::size_t(x)] =
                bilinear(width, height, cover, camera.position(point, width, height));
        }
    return g;
}

// One crossing of a line down a column of the grid (across the wind): where the cover peaks, and
// the line's width there (the run of cells above half the peak's height over the floor beside it).
struct Crossing {
    int y = 0;
    double width = 0;
};

std::vector<Crossing> crossings(const std::vector<double>& column) {
    const int n = int(column.size()), reach = int(kLineReach / kStep);
    std::vector<Crossing> found;
    for (int y = 1; y + 1 < n; ++y) {
        const double c = column[std::size_t(y)];
        if (c < kLineCover || c >= kWhitecapCover || c < column[std::size_t(y - 1)] || c < column[std::size_t(y + 1)]) continue;
        if (c == column[std::size_t(y - 1)]) continue;  // a flat top counts once
        double floor = c;
        for (int k = std::max(0, y - reach); k <= std::min(n - 1, y + reach); ++k)
            if (column[std::size_t(k)] >= 0) floor = std::min(floor, column[std::size_t(k)]);
        if (c - floor < kLineContrast) continue;
        const double half = 0.5 * (c + floor);
        int low = y, high = y;
        while (low > 0 && column[std::size_t(low - 1)] >= half) --low;
        while (high + 1 < n && column[std::size_t(high + 1)] >= half) ++high;
        found.push_back({y, (high - low + 1) * kStep});
    }
    return found;
}

// A line followed down the wind: its crossings' (along, across) positions and widths.
struct Track {
    std::vector<glm::dvec2> points;
    std::vector<double> widths;
    int last_x = 0;
    double length() const { return points.back().x - points.front().x + kStep; }
};

// Lines followed from column to column: a crossing continues the nearest track that ended within
// kLineGap metres upwind and kLineStep metres across a metre of travel; one that continues none
// starts a track (a line begins, or splits from another).
std::vector<Track> follow(const SeaGrid& g) {
    const int blur = int(kLineBlur / kStep) / 2, gap = int(kLineGap / kStep);
    std::vector<Track> done, open;
    std::vector<double> column(std::size_t(g.rows));
    for (int x = blur; x + blur < g.columns; ++x) {
        for (int y = 0; y < g.rows; ++y) {
            double sum = 0;
            bool known = true;
            for (int k = -blur; k <= blur; ++k) known = known && g.at(x + k, y) >= 0, sum += g.at(x + k, y);
            column[std::size_t(y)] = known ? sum / (2 * blur + 1) : -1;
        }
        std::vector<char> continued(open.size(), 0);
        for (const Crossing& c : crossings(column)) {
            const double across = c.y * kStep;
            int best = -1;
            double nearest = 1e300;
            for (std::size_t t = 0; t < open.size(); ++t) {
                const double travelled = (x - open[t].last_x) * kStep;
                const double off = std::abs(across - open[t].points.back().y);
                if (!continued[t] && off <= kLineStep * std::max(travelled, 1.0) && off < nearest) nearest = off, best = int(t);
            }
            if (best < 0) {
                open.push_back({{{x * kStep, across}}, {c.width}, x});
                continued.push_back(1);
                continue;
            }
            Track& t = open[std::size_t(best)];
            t.points.push_back({x * kStep, across}), t.widths.push_back(c.width), t.last_x = x;
            continued[std::size_t(best)] = 1;
        }
        for (std::size_t t = 0; t < open.size();)
            if (x - open[t].last_x > gap) done.push_back(std::move(open[t])), open.erase(open.begin() + std::ptrdiff_t(t));
            else ++t;
    }
    for (Track& t : open) done.push_back(std::move(t));
    return done;
}

// The slope of a straight line fitted to a track (across = a + slope along, least squares).
double slope(const Track& t) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const glm::dvec2& p : t.points) n += 1, sx += p.x, sy += p.y, sxx += p.x * p.x, sxy += p.x * p.y;
    const double d = n * sxx - sx * sx;
    return d > 0 ? (n * sxy - sx * sy) / d : 0;
}

}  // namespace

StreakFigures measure_streaks(const ocean_test::Pinhole& camera, int width, int height, const std::vector<double>& cover,
                              glm::dvec3 along, glm::dvec3 across, double half_side) {
    const SeaGrid g = on_the_sea(camera, width, height, cover, along, across, half_side);
    StreakFigures f;
    std::vector<std::pair<double, double>> lengths, widths;  // lengths weighted by the line's length
    double angle_sum = 0, line_length = 0;
    // Each column's crossings of lines, for the spacing.
    std::vector<std::vector<double>> across_at(std::size_t(g.columns));
    for (const Track& t : follow(g)) {
        const double length = t.length();
        if (length < kLineLength) continue;
        ++f.lines;
        lengths.emplace_back(length, length);
        for (double w : t.widths) widths.emplace_back(w, 1.0);
        angle_sum += length * std::atan(std::abs(slope(t))), line_length += length;
        for (const glm::dvec2& p : t.points) across_at[std::size_t(std::lround(p.x / kStep))].push_back(p.y);
    }
    f.angle_deg = line_length > 0 ? angle_sum / line_length * 180 / kPi : 0;
    f.length_m = weighted_median(lengths), f.width_m = weighted_median(widths);
    // Spacing: in each column, the distances between neighbouring lines' crossings; their median.
    std::vector<std::pair<double, double>> gaps;
    for (std::vector<double>& ys : across_at) {
        std::sort(ys.begin(), ys.end());
        for (std::size_t k = 1; k < ys.size(); ++k) gaps.emplace_back(ys[k] - ys[k - 1], 1.0);
    }
    f.spacing_m = weighted_median(gaps);
    f.metres_per_area = g.cover.empty() ? 0 : 1000 * line_length / (g.columns * g.rows * kStep * kStep);
    return f;
}

}  // namespace step06_test
