#include "step09_radiation/source_hull.hpp"

#include "step09_radiation/image_source.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace step09 {
namespace {

constexpr double g = ocean::kGravity;

// A piece of the hull: its middle (x, y up, z), its normal out of the hull into the water, its area.
struct Piece {
    glm::dvec3 at, normal;
    double area;
    int band;
};

// The point at polar angle `theta` from the bottom and `around` round the vertical, on a sphere of
// `radius` whose centre is `centre_height` above the surface; its outward normal is the point, less
// the centre, over the radius (on_sphere(1, ...)).
glm::dvec3 on_sphere(double radius, double theta, double around, double centre_height = 0) {
    return {radius * std::sin(theta) * std::cos(around), centre_height - radius * std::cos(theta), radius * std::sin(theta) * std::sin(around)};
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

SourceHull::SourceHull(const WaveField& field, const SourceHullSettings& s) : settings_(s), bands_(s.bands) {
    if (!(s.radius > 0) || s.radius > 0.25 * field.side()) throw ocean::Error("source hull: the radius must be positive and at most a quarter of the grid");
    if (!(std::abs(s.centre_height) < s.radius)) throw ocean::Error("source hull: the sphere's centre must be within a radius of the surface");
    if (s.bands < 1 || s.around < 3 || s.split < 2 || s.split % 2 != 0)
        throw ocean::Error("source hull: it needs a band, three panels round it and an even number of parts a panel's side");
    const double R = s.radius, c = s.centre_height;
    const double waterline = std::acos(c / R);  // the polar angle where the sphere meets the surface
    // Each panel's parts (its integrals are sums over them), and one point a band where its
    // condition is held (the middle of its first panel: all of a band's panels are alike).
    std::vector<Piece> parts, middles;
    band_area_.assign(std::size_t(bands_), 0.0);
    std::vector<double> band_normal_y(std::size_t(bands_), 0.0);  // the normals' mean vertical part
    for (int b = 0; b < bands_; ++b) {
        const double t0 = waterline * b / bands_, t1 = waterline * (b + 1) / bands_;
        const double around = ocean::kTwoPi / s.around;
        middles.push_back({on_sphere(R, 0.5 * (t0 + t1), 0.5 * around, c), on_sphere(1, 0.5 * (t0 + t1), 0.5 * around), 0, b});
        for (int p = 0; p < s.around; ++p)
            for (int u = 0; u < s.split; ++u)
                for (int v = 0; v < s.split; ++v) {
                    const double ta = t0 + (t1 - t0) * u / s.split, tb = t0 + (t1 - t0) * (u + 1) / s.split;
                    const double a0 = around * (p + double(v) / s.split), a1 = around * (p + double(v + 1) / s.split);
                    const double area = R * R * (std::cos(ta) - std::cos(tb)) * (a1 - a0);
                    const double t = 0.5 * (ta + tb), a = 0.5 * (a0 + a1);
                    parts.push_back({on_sphere(R, t, a, c), on_sphere(1, t, a), area, b});
                    band_area_[std::size_t(b)] += area;
                    band_normal_y[std::size_t(b)] += area * on_sphere(1, t, a).y;
                }
    }
    for (int b = 0; b < bands_; ++b) band_normal_y[std::size_t(b)] /= band_area_[std::size_t(b)];

    // The instantaneous part: a unit source at each part with its image sink mirrored above the
    // surface (image_source.hpp). A sheet of sources sends half its water to each side, so a band's
    // own panel also gets 1/2 of its strength along its normal (the rest are sums over parts: the
    // part nearest a band's point is half a part away, and 1/r is integrable).
    const auto n = std::size_t(bands_);
    std::vector<double> influence(n * n, 0.0);  // along the normal at band i per unit strength on band j
    std::vector<double> potential(n * n, 0.0);  // at band i's point per unit strength on band j
    for (std::size_t i = 0; i < n; ++i) {
        influence[i * n + i] += 0.5;
        const Piece& m = middles[i];
        for (const Piece& q : parts) {
            const SourceAt unit = source_with_image(m.at, q.at, m.normal);
            potential[i * n + std::size_t(q.band)] += q.area * unit.potential;
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
    // alpha: each band's area times its normal's vertical part, the weights that sum a pressure on
    // the hull into an upward force.
    std::vector<double> alpha(n);
    for (std::size_t i = 0; i < n; ++i) alpha[i] = band_area_[i] * band_normal_y[i];
    const std::vector<double> unit_heave = solve(band_normal_y);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) added_mass_ -= alpha[i] * potential[i * n + j] * unit_heave[j];
    // The sources' potential on band i per unit of the flow they cancel on band j, times band i's
    // area: what Green's identity weighs a mode's flow with (surface_source).
    area_potential_.assign(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t m = 0; m < n; ++m) area_potential_[i * n + j] += band_area_[i] * potential[i * n + m] * inverse_influence_[m * n + j];

    // The memory part, mode by mode, for the hull centred at the grid's origin. A field mode
    // phi^ e^(i k.x) / N^2 (N^2 the inverse transform's scale) reaches down as e^(|k| y): along the
    // normal n, its flow is (|k| n_y + i k.n) times it. Mirrored across x and across z, the parts
    // also come in pairs (x, z) and (-x, -z), so each sum of e^(i k.x) is its cosines' sum (the
    // sines cancel in each such pair, not in a pair mirrored across one plane only).
    cells_ = field.n();
    cell_area_ = field.settings().cell * field.settings().cell;
    const int half = cells_ / 2;
    const std::size_t kept = std::size_t(half + 1) * std::size_t(half + 1);
    const double unit = ocean::kTwoPi / field.side(), scale = 1.0 / (double(cells_) * double(cells_));
    normal_read_.assign(n, std::vector<double>(kept, 0.0));
    potential_read_.assign(n, std::vector<double>(kept, 0.0));
    for (int j = 0; j <= half; ++j)
        for (int i = 0; i <= half; ++i) {
            const glm::dvec2 k(unit * i, unit * j);
            const double length = std::sqrt(k.x * k.x + k.y * k.y);
            const std::size_t mode = quarter(i, j);
            for (const Piece& q : parts) {
                const double down = std::exp(length * q.at.y);
                const double phase = k.x * q.at.x + k.y * q.at.z;
                const double share = q.area / band_area_[std::size_t(q.band)] * down * scale;
                const auto b = std::size_t(q.band);
                normal_read_[b][mode] += share * (length * q.normal.y * std::cos(phase) - (k.x * q.normal.x + k.y * q.normal.z) * std::sin(phase));
                potential_read_[b][mode] += share * std::cos(phase);
            }
        }
    // The heave's table, read and written alike (surface_source): the force a mode's pressure puts
    // on the hull, its own pressure on the hull less the change of the sources that cancel its flow,
    // sum_i alpha_i (Psi_i - sum_j P_ij N_j) with P = potential S (S the influence's inverse): per
    // unit of dphi^/dt. Its transpose weighs the flow by (S^T potential^T alpha).
    std::vector<double> through(n, 0.0), weighed(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t m = 0; m < n; ++m) through[m] += alpha[i] * potential[i * n + m];
    for (std::size_t m = 0; m < n; ++m)
        for (std::size_t j = 0; j < n; ++j) weighed[j] += through[m] * inverse_influence_[m * n + j];
    heave_.assign(kept, 0.0);
    for (std::size_t mode = 0; mode < kept; ++mode)
        for (std::size_t b = 0; b < n; ++b) heave_[mode] += alpha[b] * potential_read_[b][mode] - weighed[b] * normal_read_[b][mode];
}

std::size_t SourceHull::quarter(int i, int j) const {
    const int a = std::min(i, cells_ - i), b = std::min(j, cells_ - j);
    return std::size_t(b) * std::size_t(cells_ / 2 + 1) + std::size_t(a);
}

void SourceHull::phases(const WaveField& field, glm::dvec2 centre, std::vector<Complex>& along_x, std::vector<Complex>& along_z) const {
    const glm::dvec2 offset = centre - field.cell_centre(0, 0);
    along_x.resize(std::size_t(cells_));
    along_z.resize(std::size_t(cells_));
    for (int i = 0; i < cells_; ++i) {
        const glm::dvec2 k = field.wavenumber(i, i);
        along_x[std::size_t(i)] = Complex(std::cos(k.x * offset.x), std::sin(k.x * offset.x));
        along_z[std::size_t(i)] = Complex(std::cos(k.y * offset.y), std::sin(k.y * offset.y));
    }
}

double SourceHull::volume() const {
    const double R = settings_.radius, d = R - settings_.centre_height;
    return ocean::kPi * d * d * (3 * R - d) / 3;
}
double SourceHull::waterplane() const {
    const double R = settings_.radius, c = settings_.centre_height;
    return ocean::kPi * (R * R - c * c);
}
double SourceHull::wetted_area() const {
    double area = 0;
    for (double a : band_area_) area += a;
    return area;
}

std::vector<double> SourceHull::solve(const std::vector<double>& rhs) const {
    const auto n = std::size_t(bands_);
    std::vector<double> x(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) x[i] += inverse_influence_[i * n + j] * rhs[j];
    return x;
}

SourceHull::Reading SourceHull::read(const WaveField& field, glm::dvec2 centre) const {
    // The field's two spectra: eta^ and phi^, from one transform of eta + i phi.
    const std::size_t modes = field.heights().size();
    std::vector<Complex> both(modes);
    for (std::size_t c = 0; c < modes; ++c) both[c] = Complex(field.heights()[c], field.potentials()[c]);
    field.fft().forward(both);
    std::vector<Complex> along_x, along_z;
    phases(field, centre, along_x, along_z);
    const auto n = std::size_t(bands_);
    Reading r;
    r.normal_speed.assign(n, 0.0);
    r.normal_rate.assign(n, 0.0);
    for (int j = 0; j < cells_; ++j)
        for (int i = 0; i < cells_; ++i) {
            const std::size_t mode = std::size_t(j) * std::size_t(cells_) + std::size_t(i);
            const std::size_t partner = std::size_t((cells_ - j) % cells_) * std::size_t(cells_) + std::size_t((cells_ - i) % cells_);
            const Complex mirrored = std::conj(both[partner]);
            const Complex at_centre = times(along_x[std::size_t(i)], along_z[std::size_t(j)]);
            // The mode's potential and height where the hull is (the readings are real).
            const double phi = times(-0.5 * times_i(both[mode] - mirrored), at_centre).real();
            const double eta = times(0.5 * (both[mode] + mirrored), at_centre).real();
            const double phi_rate = -g * eta;  // the surface's condition, the forcing's P left out: dphi^/dt = -g eta^
            const std::size_t kept = quarter(i, j);
            // The waves' pressure on the hull, and the change of the sources that cancel their flow
            // along it (their dphi/dt is part of the pressure as well): the heave's table.
            r.wave_force += phi_rate * heave_[kept];
            for (std::size_t b = 0; b < n; ++b) {
                r.normal_speed[b] += phi * normal_read_[b][kept];
                r.normal_rate[b] += phi_rate * normal_read_[b][kept];
            }
        }
    return r;
}

std::vector<double> SourceHull::surface_source(const Reading& reading, double heave_speed, double ahead, const WaveField& field,
                                               glm::dvec2 centre) const {
    // Green's identity over the water: what the sources put through the free surface, per mode,
    // is sum_i dS_i (Psi_i dphi_s/dn - phi_s N_i) over the hull, where dphi_s/dn is the hull's speed
    // along its normal less the field's flow there (held at the step's middle), and phi_s the
    // sources' potential. The hull's own heave goes through its table, the one the force is read
    // with; the field's flow, cancelled, through Psi and N.
    const auto n = std::size_t(bands_);
    std::vector<double> cancel(n), on_psi(n), on_flow(n, 0.0);
    for (std::size_t b = 0; b < n; ++b) cancel[b] = -(reading.normal_speed[b] + ahead * reading.normal_rate[b]);
    for (std::size_t i = 0; i < n; ++i) {
        on_psi[i] = band_area_[i] * cancel[i];
        for (std::size_t j = 0; j < n; ++j) on_flow[i] -= area_potential_[i * n + j] * cancel[j];
    }
    std::vector<Complex> along_x, along_z;
    phases(field, centre, along_x, along_z);
    std::vector<Complex> spectrum(std::size_t(cells_) * std::size_t(cells_));
    for (int j = 0; j < cells_; ++j)
        for (int i = 0; i < cells_; ++i) {
            const std::size_t kept = quarter(i, j);
            double through = heave_speed * heave_[kept];
            for (std::size_t b = 0; b < n; ++b) through += on_psi[b] * potential_read_[b][kept] + on_flow[b] * normal_read_[b][kept];
            // At the hull's place (a source at x_s puts e^(-i k.x_s) into mode k), a value a cell.
            spectrum[std::size_t(j) * std::size_t(cells_) + std::size_t(i)] =
                through / cell_area_ * std::conj(times(along_x[std::size_t(i)], along_z[std::size_t(j)]));
        }
    field.fft().inverse(spectrum);
    std::vector<double> source(spectrum.size());
    for (std::size_t c = 0; c < source.size(); ++c) source[c] = spectrum[c].real();
    return source;
}

}  // namespace step09
