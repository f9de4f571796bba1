#include "step08_wakes/wake_experiments.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace step08 {

double transverse_wavelength(double speed) { return ocean::kTwoPi * speed * speed / ocean::kGravity; }
double froude_number(double speed, double length) { return speed / std::sqrt(ocean::kGravity * length); }

WaveFieldSettings deep_field(int n, double cell, double layer, double rate) {
    WaveFieldSettings settings;
    settings.n = n;
    settings.cell = cell;
    settings.absorbing_width = layer * n * cell;
    settings.absorbing_rate = rate;
    return settings;
}

TowedWake tow(const TowedPatch& t) {
    WaveField field(deep_field(t.n, t.cell, 0.12, 4));
    const double sigma = t.length / 4;
    const double dt = std::min(t.cell / t.speed, 1.0 / 30);  // the patch moves at most a cell a step
    const int steps = int(std::ceil(t.seconds / dt));
    Forcing forcing;
    forcing.pressure.assign(std::size_t(t.n) * std::size_t(t.n), 0.0);
    glm::dvec2 patch(0.0);
    for (int s = 0; s < steps; ++s) {
        patch = {t.speed * (s + 0.5) * dt, 0.0};  // the middle of the step
        field.follow(patch - glm::dvec2(0.25 * field.side(), 0));
        for (int j = 0; j < t.n; ++j)
            for (int i = 0; i < t.n; ++i) {
                const glm::dvec2 d = field.cell_centre(i, j) - patch;
                forcing.pressure[std::size_t(j) * std::size_t(t.n) + std::size_t(i)] =
                    t.pressure * std::exp(-0.5 * (d.x * d.x + d.y * d.y) / (sigma * sigma));
            }
        field.step(dt, forcing);
    }
    return {std::move(field), {t.speed * steps * dt, 0.0}};
}

namespace {

// Across a caustic the waves' amplitude follows Airy's function Ai of the distance across it (an
// Airy wave: largest a little inside, dying away outside): the caustic itself, where Ai's argument
// is 0, is where it has fallen to Ai(0) / max Ai = 0.35503 / 0.53566 of its peak.
constexpr double kAiryAtCaustic = 0.35503 / 0.53566;

// Across the wake at `behind` metres behind the patch: for y = cell, 2 cell, ... the envelope of
// the waves (the largest |eta| within half a transverse wavelength along the track), the larger of
// the two sides. Out to the layer, or to y = x (45 degrees).
std::vector<double> envelope_across(const TowedWake& wake, double speed, double behind) {
    const WaveField& f = wake.field;
    // Half a transverse wavelength, or a tenth of the distance behind where that is shorter (a
    // fast source's transverse waves are long, its largest waves short).
    const double cell = f.settings().cell, half_wave = std::min(0.5 * transverse_wavelength(speed), 0.1 * behind);
    const double y_max = std::min(behind, 0.5 * f.side() - f.settings().absorbing_width);
    std::vector<double> envelope;
    for (double y = cell; y <= y_max; y += cell) {
        double largest = 0;
        for (int side = -1; side <= 1; side += 2)
            for (double a = -half_wave; a <= half_wave; a += cell)
                largest = std::max(largest, std::abs(f.height_at(wake.patch + glm::dvec2(-behind + a, side * y))));
        envelope.push_back(largest);
    }
    return envelope;
}

// The median over distances behind from `from` to `to` (every cell) of atan(y / x) for the y
// that `pick` chooses from each envelope (its index; y = (index + 1) cell).
template <class Pick>
double median_angle(const TowedWake& wake, double speed, double from, double to, Pick pick) {
    const double cell = wake.field.settings().cell;
    std::vector<double> angles;
    for (double behind = from; behind <= to; behind += cell) {
        const std::vector<double> envelope = envelope_across(wake, speed, behind);
        if (envelope.empty()) continue;
        angles.push_back(std::atan2((double(pick(envelope)) + 1) * cell, behind) * 180 / ocean::kPi);
    }
    std::sort(angles.begin(), angles.end());
    return angles.empty() ? 0 : angles[angles.size() / 2];
}

}  // namespace

double largest_wave_angle(const TowedWake& wake, double speed, double from, double to) {
    return median_angle(wake, speed, from, to, [](const std::vector<double>& e) {
        return std::size_t(std::max_element(e.begin(), e.end()) - e.begin());
    });
}

double wake_edge_angle(const TowedWake& wake, double speed, double from, double to) {
    return median_angle(wake, speed, from, to, [](const std::vector<double>& e) {
        const double half = kAiryAtCaustic * *std::max_element(e.begin(), e.end());
        std::size_t edge = e.size() - 1;
        while (edge > 0 && e[edge] < half) --edge;
        return edge;
    });
}

std::vector<double> ring_crests(const WaveField& field, double from, double to) {
    const double cell = field.settings().cell;
    const glm::dvec2 centre = field.cell_centre(field.n() / 2, field.n() / 2);
    // The field averaged over circles (every direction alike), sampled every tenth of a cell.
    const double dr = 0.1 * cell;
    std::vector<double> radius, mean;
    for (double r = from; r <= to; r += dr) {
        const int around = std::max(16, int(ocean::kTwoPi * r / cell));
        double sum = 0;
        for (int a = 0; a < around; ++a) {
            const double angle = ocean::kTwoPi * (a + 0.5) / around;
            sum += field.height_at(centre + r * glm::dvec2(std::cos(angle), std::sin(angle)));
        }
        radius.push_back(r);
        mean.push_back(sum / around);
    }
    std::vector<double> crests;
    for (std::size_t i = 1; i + 1 < mean.size(); ++i)
        if (mean[i] > mean[i - 1] && mean[i] >= mean[i + 1] && mean[i] > 0) {
            // The parabola through the three samples puts the crest between them.
            const double curve = mean[i - 1] - 2 * mean[i] + mean[i + 1];
            const double shift = curve < 0 ? 0.5 * (mean[i - 1] - mean[i + 1]) / curve : 0;
            crests.push_back(radius[i] + shift * dr);
        }
    return crests;
}

}  // namespace step08
