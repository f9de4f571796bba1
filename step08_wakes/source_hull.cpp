#include "step08_wakes/source_hull.hpp"

#include "step08_wakes/image_source.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <utility>

namespace step08 {
namespace {

constexpr double g = ocean::kGravity;
// The share of a source's water that goes through the surface, its image's answer included: a
// source sends half up; a sink above pulls as much again up (all of it), a source pushes it back.
constexpr double kThroughSurface = 0.5 * (1 - kImageStrength);

// A piece of the hull: its middle (x, y up, z), its normal out of the hull into the water, its area.
struct Piece {
    glm::dvec3 at, normal;
    double area;
    int band;
};

// The point at polar angle `theta` from the bottom and `around` round the vertical, on a sphere of
// `radius` centred at `centre` on the surface; its outward normal is the point over the radius.
glm::dvec3 on_sphere(double radius, double theta, double around) {
    return {radius * std::sin(theta) * std::cos(around), -radius * std::cos(theta), radius * std::sin(theta) * std::sin(around)};
}

// Solves a x = rhs (n x n, row major) by Gaussian elimination with partial pivoting: the influence
// matrix is small (bands x bands) and not symmetric (each band's condition is held at one point,
// its strength spread over its area).
std::vector<double> solve_general(std::vector<double> a, std::vector<double> rhs, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::abs(a[i * n + k]) > std::abs(a[pivot * n + k])) pivot = i;
        for (std::size_t j = 0; j < n; ++j) std::swap(a[k * n + j], a[pivot * n + j]);
        std::swap(rhs[k], rhs[pivot]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = a[i * n + k] / a[k * n + k];
            for (std::size_t j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
            rhs[i] -= f * rhs[k];
        }
    }
    for (std::size_t k = n; k-- > 0;) {
        for (std::size_t j = k + 1; j < n; ++j) rhs[k] -= a[k * n + j] * rhs[j];
        rhs[k] /= a[k * n + k];
    }
    return rhs;
}

}  // namespace

SourceHull::SourceHull(const WaveField& field, glm::dvec2 centre, const SourceHullSettings& s) : settings_(s), bands_(s.bands) {
    if (!(s.radius > 0) || s.radius > 0.25 * field.side()) throw ocean::Error("source hull: the radius must be positive and at most a quarter of the grid");
    if (s.bands < 1 || s.around < 3 || s.split < 2 || s.split % 2 != 0)
        throw ocean::Error("source hull: it needs a band, three panels round it and an even number of parts a panel's side");
    const double R = s.radius, half_pi = 0.5 * ocean::kPi;
    // Each panel's parts (its integrals are sums over them), and one point a band where its
    // condition is held (the middle of its first panel: all of a band's panels are alike).
    std::vector<Piece> parts, middles;
    band_area_.assign(std::size_t(bands_), 0.0);
    band_normal_y_.assign(std::size_t(bands_), 0.0);
    for (int b = 0; b < bands_; ++b) {
        const double t0 = half_pi * b / bands_, t1 = half_pi * (b + 1) / bands_;
        const double around = ocean::kTwoPi / s.around;
        middles.push_back({on_sphere(R, 0.5 * (t0 + t1), 0.5 * around), on_sphere(1, 0.5 * (t0 + t1), 0.5 * around), 0, b});
        for (int p = 0; p < s.around; ++p)
            for (int u = 0; u < s.split; ++u)
                for (int v = 0; v < s.split; ++v) {
                    const double ta = t0 + (t1 - t0) * u / s.split, tb = t0 + (t1 - t0) * (u + 1) / s.split;
                    const double a0 = around * (p + double(v) / s.split), a1 = around * (p + double(v + 1) / s.split);
                    const double area = R * R * (std::cos(ta) - std::cos(tb)) * (a1 - a0);
                    const double t = 0.5 * (ta + tb), a = 0.5 * (a0 + a1);
                    parts.push_back({on_sphere(R, t, a), on_sphere(1, t, a), area, b});
                    band_area_[std::size_t(b)] += area;
                    band_normal_y_[std::size_t(b)] += area * on_sphere(1, t, a).y;
                }
    }
    for (int b = 0; b < bands_; ++b) band_normal_y_[std::size_t(b)] /= band_area_[std::size_t(b)];

    // The instantaneous part: a unit source at each part with its image sink mirrored above the
    // surface (image_source.hpp). A sheet of sources sends half its water to each side, so a band's
    // own panel also gets 1/2 of its strength along its normal (the rest are sums over parts: the
    // part nearest a band's point is half a part away, and 1/r is integrable).
    const auto n = std::size_t(bands_);
    std::vector<double> influence(n * n, 0.0);  // along the normal at band i per unit strength on band j
    potential_.assign(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        influence[i * n + i] += 0.5;
        const Piece& m = middles[i];
        for (const Piece& q : parts) {
            const SourceAt unit = source_with_image(m.at, q.at, m.normal);
            potential_[i * n + std::size_t(q.band)] += q.area * unit.potential;
            influence[i * n + std::size_t(q.band)] += q.area * unit.along;
        }
    }
    // The matrix stays as it is: its inverse, once, turns each step's right-hand sides into strengths.
    inverse_influence_.assign(n * n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        std::vector<double> unit(n, 0.0);
        unit[j] = 1;
        const std::vector<double> column = solve_general(influence, unit, n);
        for (std::size_t i = 0; i < n; ++i) inverse_influence_[i * n + j] = column[i];
    }
    // Heaving at unit speed, the hull's speed along its normal is its normal's vertical part; the
    // pressure -rho dphi/dt of the strengths that follow it, summed over the hull, is the added mass.
    const std::vector<double> unit_heave = solve(band_normal_y_);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) added_mass_ -= band_area_[i] * band_normal_y_[i] * potential_[i * n + j] * unit_heave[j];

    // The memory part, mode by mode. A field mode phi^ e^(i k.(x - x0)) / N^2 (x0 cell (0, 0)'s
    // centre, N^2 the inverse transform's scale) reaches down as e^(|k| y): along the normal
    // n, its flow is (|k| n_y + i k.n) times it. A source of unit strength d deep, with its image,
    // puts e^(-|k| d) through the surface, per mode; over a cell's area, on the grid.
    const int cells = field.n();
    const std::size_t modes = std::size_t(cells) * std::size_t(cells);
    const glm::dvec2 x0 = field.cell_centre(0, 0);
    const double cell_area = field.settings().cell * field.settings().cell, scale = 1.0 / double(modes);
    normal_read_.assign(n, std::vector<Complex>(modes));
    potential_read_.assign(n, std::vector<Complex>(modes));
    std::vector<std::vector<Complex>> put(n, std::vector<Complex>(modes));
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const glm::dvec2 k = field.wavenumber(i, j);
            const double length = std::sqrt(k.x * k.x + k.y * k.y);
            const std::size_t mode = std::size_t(j) * std::size_t(cells) + std::size_t(i);
            for (const Piece& q : parts) {
                const double down = std::exp(length * q.at.y);
                const double phase = k.x * (centre.x + q.at.x - x0.x) + k.y * (centre.y + q.at.z - x0.y);
                const Complex wave(std::cos(phase), std::sin(phase));
                const double share = q.area / band_area_[std::size_t(q.band)] * down * scale;
                const auto b = std::size_t(q.band);
                normal_read_[b][mode] += share * times(Complex(length * q.normal.y, k.x * q.normal.x + k.y * q.normal.z), wave);
                potential_read_[b][mode] += share * wave;
                put[b][mode] += kThroughSurface * q.area * down / cell_area * std::conj(wave);
            }
        }
    source_pattern_.assign(n, std::vector<double>(modes));
    for (std::size_t b = 0; b < n; ++b) {
        field.fft().inverse(put[b]);
        for (std::size_t c = 0; c < modes; ++c) source_pattern_[b][c] = put[b][c].real() * scale;
    }
}

double SourceHull::volume() const { return 2.0 / 3.0 * ocean::kPi * std::pow(settings_.radius, 3); }
double SourceHull::waterplane() const { return ocean::kPi * settings_.radius * settings_.radius; }

std::vector<double> SourceHull::solve(const std::vector<double>& rhs) const {
    const auto n = std::size_t(bands_);
    std::vector<double> x(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) x[i] += inverse_influence_[i * n + j] * rhs[j];
    return x;
}

SourceHull::Reading SourceHull::read(const WaveField& field) const {
    // The field's two spectra: eta^ and phi^, from one transform of eta + i phi.
    const std::size_t modes = field.heights().size();
    const int cells = field.n();
    std::vector<Complex> both(modes);
    for (std::size_t c = 0; c < modes; ++c) both[c] = Complex(field.heights()[c], field.potentials()[c]);
    field.fft().forward(both);
    const auto n = std::size_t(bands_);
    Reading r;
    r.normal_speed.assign(n, 0.0);
    r.normal_rate.assign(n, 0.0);
    std::vector<double> pressure_rate(n, 0.0);  // dphi/dt of the field at the hull, a band's mean
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const std::size_t mode = std::size_t(j) * std::size_t(cells) + std::size_t(i);
            const std::size_t partner = std::size_t((cells - j) % cells) * std::size_t(cells) + std::size_t((cells - i) % cells);
            const Complex mirrored = std::conj(both[partner]);
            const Complex eta = 0.5 * (both[mode] + mirrored), phi = -0.5 * times_i(both[mode] - mirrored);
            const Complex phi_rate = -g * eta;  // the surface's condition: dphi^/dt = -g eta^
            for (std::size_t b = 0; b < n; ++b) {
                r.normal_speed[b] += times(phi, normal_read_[b][mode]).real();
                r.normal_rate[b] += times(phi_rate, normal_read_[b][mode]).real();
                pressure_rate[b] += times(phi_rate, potential_read_[b][mode]).real();
            }
        }
    // The field's flow along the normal changes, so the sources change to cancel it; their
    // dphi/dt is part of the pressure as well.
    const std::vector<double> answer = solve(r.normal_rate);
    for (std::size_t i = 0; i < n; ++i) {
        double sources_rate = 0;
        for (std::size_t j = 0; j < n; ++j) sources_rate -= potential_[i * n + j] * answer[j];
        r.wave_force += band_area_[i] * band_normal_y_[i] * (pressure_rate[i] + sources_rate);
    }
    return r;
}

std::vector<double> SourceHull::strengths(const Reading& reading, double heave_speed, double ahead) const {
    std::vector<double> rhs(static_cast<std::size_t>(bands_));
    for (std::size_t b = 0; b < rhs.size(); ++b)
        rhs[b] = heave_speed * band_normal_y_[b] - (reading.normal_speed[b] + ahead * reading.normal_rate[b]);
    return solve(rhs);
}

std::vector<double> SourceHull::surface_source(const std::vector<double>& strengths) const {
    std::vector<double> source(source_pattern_.empty() ? 0 : source_pattern_[0].size(), 0.0);
    for (std::size_t b = 0; b < strengths.size() && b < source_pattern_.size(); ++b)
        for (std::size_t c = 0; c < source.size(); ++c) source[c] += strengths[b] * source_pattern_[b][c];
    return source;
}

}  // namespace step08
