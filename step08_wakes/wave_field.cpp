#include "step08_wakes/wave_field.hpp"

#include "step08_wakes/mode_step.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace step08 {
namespace {

constexpr double g = ocean::kGravity;

// The transform of two real fields at once: x + i y forward, then X^(k) = (C(k) + C*(-k)) / 2 and
// Y^(k) = (C(k) - C*(-k)) / 2i, since a real field's transform has X^(-k) = X^*(k).
struct TwoSpectra {
    Complex first, second;
};
TwoSpectra separate(Complex at_k, Complex at_minus_k) {
    const Complex mirrored = std::conj(at_minus_k);
    return {(at_k + mirrored) * 0.5, -0.5 * times_i(at_k - mirrored)};
}

}  // namespace

bool same_grid(const WaveFieldSettings& a, const WaveFieldSettings& b) {
    return a.n == b.n && a.cell == b.cell && a.depth == b.depth;
}

double vertical_speed_factor(double wavenumber, double depth) {
    return std::isinf(depth) ? wavenumber : wavenumber * std::tanh(wavenumber * depth);
}

WaveField::WaveField(const WaveFieldSettings& settings) : settings_(settings), fft_(settings.n) {
    const auto fail = [](const std::string& what) { throw ocean::Error("wave field: " + what); };
    if (!(settings.cell > 0) || !std::isfinite(settings.cell)) fail("the cell must be a positive length");
    if (!(settings.depth > 0)) fail("the depth must be positive (infinite for deep water)");
    if (!(settings.absorbing_width >= 0) || settings.absorbing_width > 0.5 * side())
        fail("the absorbing layer must be from 0 to half the grid's side wide");
    if (!(settings.absorbing_rate >= 0) || !std::isfinite(settings.absorbing_rate))
        fail("the absorbing rate must be a finite rate, 0 or more");
    const std::size_t cells = std::size_t(settings.n) * std::size_t(settings.n);
    eta_.assign(cells, 0.0);
    phi_.assign(cells, 0.0);
    work_.resize(cells);
    // The layer: the rate grows as the square of the depth into it, from 0 at its inner edge (a
    // smooth start reflects less) to absorbing_rate at the grid's edge; corners take the larger.
    absorbing_rate_.assign(cells, 0.0);
    const int n = settings.n;
    // Each mode's K, once: every step and the energy read it.
    speed_factor_.resize(cells);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 k = wavenumber(i, j);
            speed_factor_[index(i, j)] = vertical_speed_factor(std::hypot(k.x, k.y), settings.depth);
        }
    const double width = settings.absorbing_width;
    if (width > 0)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double to_edge = settings.cell * (std::min({i, j, n - 1 - i, n - 1 - j}) + 0.5);
                const double into = std::max(0.0, (width - to_edge) / width);
                absorbing_rate_[index(i, j)] = settings.absorbing_rate * into * into;
            }
}

glm::dvec2 WaveField::wavenumber(int i, int j) const {
    const int n = settings_.n;
    const double unit = ocean::kTwoPi / side();
    return {unit * (i < n / 2 ? i : i - n), unit * (j < n / 2 ? j : j - n)};
}

void WaveField::step(double dt, const Forcing& forcing) {
    turn(dt, forcing);
    absorb(dt);
}

void WaveField::turn(double dt, const Forcing& forcing) {
    if (!(dt > 0) || !std::isfinite(dt)) throw ocean::Error("wave field: a step must last a positive time");
    const int n = settings_.n;
    const std::size_t cells = eta_.size();
    const bool pressed = !forcing.pressure.empty(), fed = !forcing.source.empty();
    if ((pressed && forcing.pressure.size() != cells) || (fed && forcing.source.size() != cells))
        throw ocean::Error("wave field: forcing of the wrong size");
    for (std::size_t c = 0; c < cells; ++c) work_[c] = Complex(eta_[c], phi_[c]);
    fft_.forward(work_);
    if (pressed || fed) {  // both real fields in one transform, as the field's own two
        forcing_work_.resize(cells);
        for (std::size_t c = 0; c < cells; ++c)
            forcing_work_[c] = Complex(pressed ? forcing.pressure[c] : 0.0, fed ? forcing.source[c] : 0.0);
        fft_.forward(forcing_work_);
    }
    // Each pair (k, -k) at once: both are read before either is written.
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int mi = (n - i) % n, mj = (n - j) % n;
            const std::size_t a = index(i, j), b = index(mi, mj);
            if (b < a) continue;  // done with its partner
            const Complex at_a = work_[a], at_b = work_[b];
            Complex out_a, out_b;
            for (int side = 0; side < (a == b ? 1 : 2); ++side) {
                const std::size_t here = side == 0 ? a : b;
                const TwoSpectra field = side == 0 ? separate(at_a, at_b) : separate(at_b, at_a);
                const TwoSpectra push = !(pressed || fed) ? TwoSpectra{}
                                        : side == 0 ? separate(forcing_work_[a], forcing_work_[b])
                                                    : separate(forcing_work_[b], forcing_work_[a]);
                const Mode turned = turn_mode({field.first, field.second}, speed_factor_[here], dt, push.first, push.second);
                (side == 0 ? out_a : out_b) = turned.eta + times_i(turned.phi);
            }
            work_[a] = out_a;
            if (a != b) work_[b] = out_b;
        }
    fft_.inverse(work_);
    const double scale = 1.0 / (double(n) * double(n));
    for (std::size_t c = 0; c < cells; ++c) {
        eta_[c] = work_[c].real() * scale;
        phi_[c] = work_[c].imag() * scale;
    }
}

void WaveField::absorb(double dt) {
    if (settings_.absorbing_width <= 0) return;
    for (std::size_t c = 0; c < eta_.size(); ++c) {
        if (absorbing_rate_[c] == 0) continue;
        const double keep = std::exp(-absorbing_rate_[c] * dt);
        eta_[c] *= keep;
        phi_[c] *= keep;
    }
}

void WaveField::follow(glm::dvec2 centre) {
    const auto to_cell = [&](double x) { return std::int64_t(std::llround(x / settings_.cell)); };
    const std::int64_t di = to_cell(centre.x) - origin_i_, dj = to_cell(centre.y) - origin_j_;
    if (di == 0 && dj == 0) return;
    origin_i_ += di;
    origin_j_ += dj;
    const int n = settings_.n;
    for (auto* field : {&eta_, &phi_}) {
        std::vector<double> moved(field->size(), 0.0);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::int64_t from_i = i + di, from_j = j + dj;
                if (from_i >= 0 && from_i < n && from_j >= 0 && from_j < n)
                    moved[index(i, j)] = (*field)[index(int(from_i), int(from_j))];
            }
        *field = std::move(moved);
    }
}

glm::dvec2 WaveField::cell_centre(int i, int j) const {
    const int half = settings_.n / 2;
    return {double(origin_i_ + i - half) * settings_.cell, double(origin_j_ + j - half) * settings_.cell};
}

void WaveField::add_impulse(glm::dvec2 at, double impulse, double radius) {
    if (!(radius > 0) || !std::isfinite(impulse)) throw ocean::Error("wave field: an impulse needs a positive radius");
    const double norm = 1.0 / (ocean::kTwoPi * radius * radius);  // the Gaussian integrates to 1
    for (int j = 0; j < settings_.n; ++j)
        for (int i = 0; i < settings_.n; ++i) {
            const glm::dvec2 d = cell_centre(i, j) - at;
            const double r2 = (d.x * d.x + d.y * d.y) / (radius * radius);
            if (r2 < 50) phi_[index(i, j)] -= impulse * norm * std::exp(-0.5 * r2);
        }
}

bool WaveField::bilinear_taps(glm::dvec2 at, Taps& taps) const {
    const glm::dvec2 corner = cell_centre(0, 0);
    const double u = (at.x - corner.x) / settings_.cell, v = (at.y - corner.y) / settings_.cell;
    const int n = settings_.n;
    if (!(u >= 0 && v >= 0 && u < n - 1 && v < n - 1)) return false;
    const int i = int(u), j = int(v);
    const double fu = u - i, fv = v - j;
    taps = {{index(i, j), index(i + 1, j), index(i, j + 1), index(i + 1, j + 1)},
            {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv}};
    return true;
}

bool WaveField::covers(glm::dvec2 at) const {
    Taps taps;
    return bilinear_taps(at, taps);
}

double WaveField::height_at(glm::dvec2 at) const {
    Taps taps;
    if (!bilinear_taps(at, taps)) return 0;
    double height = 0;
    for (int t = 0; t < 4; ++t) height += taps.weights[t] * eta_[taps.cells[t]];
    return height;
}

double WaveField::energy() const {
    const int n = settings_.n;
    for (std::size_t c = 0; c < eta_.size(); ++c) work_[c] = Complex(eta_[c], phi_[c]);
    fft_.forward(work_);
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const TwoSpectra f = separate(work_[index(i, j)], work_[index((n - i) % n, (n - j) % n)]);
            sum += g * std::norm(f.first) + speed_factor_[index(i, j)] * std::norm(f.second);
        }
    // Parseval: sum over cells of x^2 = sum over modes of |X^|^2 / n^2; times the cell's area.
    return 0.5 * sum * settings_.cell * settings_.cell / (double(n) * double(n));
}

}  // namespace step08
