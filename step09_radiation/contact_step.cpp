#include "step09_radiation/contact_step.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace step09 {
namespace {

// The pushes q >= 0 with A q = b where they push and A q >= b where they do not (the water there
// ends at or under the hull): every point first, then rounds that let go of the points a solution
// pulls and take in those it leaves under water, until none changes (a few rounds); should points
// keep changing, the last round's solution after m + 1 rounds.
std::vector<double> solve_pushing(const std::vector<double>& a, const std::vector<double>& b) {
    const std::size_t m = b.size();
    std::vector<char> active(m, 1);
    std::vector<double> q(m, 0.0);
    for (std::size_t round = 0; round <= m; ++round) {
        std::vector<std::size_t> in;
        for (std::size_t i = 0; i < m; ++i)
            if (active[i]) in.push_back(i);
        std::vector<double> sub(in.size() * in.size()), x(in.size());
        for (std::size_t r = 0; r < in.size(); ++r) {
            for (std::size_t c = 0; c < in.size(); ++c) sub[r * in.size() + c] = a[in[r] * m + in[c]];
            x[r] = b[in[r]];
        }
        if (!in.empty()) solve_symmetric(sub, x, in.size());
        std::fill(q.begin(), q.end(), 0.0);
        for (std::size_t r = 0; r < in.size(); ++r) q[in[r]] = x[r];
        bool changed = false;
        for (std::size_t i = 0; i < m; ++i) {
            if (active[i] && q[i] < 0) {
                active[i] = false, changed = true;
                continue;
            }
            if (active[i]) continue;
            double reached = 0;  // how far the pushes bring the water down, and the hull up, at i
            for (std::size_t j = 0; j < m; ++j) reached += a[i * m + j] * q[j];
            if (b[i] - reached > 1e-9) active[i] = true, changed = true;  // the water would end over the hull
        }
        if (!changed) break;
    }
    return q;
}

}  // namespace

void solve_symmetric(std::vector<double>& a, std::vector<double>& b, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j) {
        double d = a[j * m + j];
        for (std::size_t k = 0; k < j; ++k) d -= a[j * m + k] * a[j * m + k];
        if (!(d > 0)) throw ocean::Error("wave field: a contact's system is not positive definite");
        a[j * m + j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < m; ++i) {
            double s = a[i * m + j];
            for (std::size_t k = 0; k < j; ++k) s -= a[i * m + k] * a[j * m + k];
            a[i * m + j] = s / a[j * m + j];
        }
    }
    for (std::size_t i = 0; i < m; ++i) {  // L y = b
        for (std::size_t k = 0; k < i; ++k) b[i] -= a[i * m + k] * b[k];
        b[i] /= a[i * m + i];
    }
    for (std::size_t i = m; i-- > 0;) {  // L^T x = y
        for (std::size_t k = i + 1; k < m; ++k) b[i] -= a[k * m + i] * b[k];
        b[i] /= a[i * m + i];
    }
}

void ContactStep::make_kernel(const WaveFieldSettings& settings, double dt) {
    if (kernel_for_ == dt && step08::same_grid(kernel_grid_, settings) && !kernel_.empty()) return;
    // A unit p / rho on cell 0, held for dt over water at rest with no absorbing layer: the
    // field's own step gives each mode -(P^ / g)(1 - cos omega dt), and the heights it leaves are
    // the kernel by offset from cell 0 (the grid is periodic).
    WaveFieldSettings bare = settings;
    bare.absorbing_width = 0;
    WaveField unit(bare);
    Forcing push;
    push.pressure.assign(unit.heights().size(), 0.0);
    push.pressure[0] = 1;
    unit.step(dt, push);
    kernel_ = unit.heights();
    kernel_for_ = dt;
    kernel_grid_ = settings;
}

std::vector<double> ContactStep::step(WaveField& field, double dt, const Contact& contact, const Forcing& forcing) {
    const std::size_t m = contact.target.size(), taps = std::size_t(std::max(contact.taps, 1));
    if (contact.cells.size() != m * taps || contact.compliance.size() != m * m ||
        !(contact.weights.empty() || contact.weights.size() == m * taps))
        throw ocean::Error("contact: its cells, weights or compliance do not match its points");
    field.step(dt, forcing);  // where the surface goes if nothing pushes on it
    make_kernel(field.settings(), dt);
    const int n = field.n();
    const auto offset = [n](std::size_t to, std::size_t from) {  // index of the periodic offset
        const int di = (int(to % std::size_t(n)) - int(from % std::size_t(n)) + n) % n;
        const int dj = (int(to / std::size_t(n)) - int(from / std::size_t(n)) + n) % n;
        return std::size_t(dj) * std::size_t(n) + std::size_t(di);
    };
    const auto weight = [&](std::size_t tap) { return contact.weights.empty() ? 1.0 : contact.weights[tap]; };
    // The pushes Q_j at the contact points: the surface there ends at the hull,
    //     eta_free(i) + sum_j kernel(i, j) Q_j = target(i) + sum_j compliance(i, j) Q_j
    // (the hull moves up by compliance Q as the water pushes it), where kernel(i, j) is how far a
    // unit push at point j, a pressure of w / dA on each of its cells, moves the surface read at
    // point i: the sum over their taps of w w' kernel(cell - cell') / dA. A symmetric positive
    // definite system: -kernel is (1 - cos omega dt) / g >= 0 mode by mode, and the compliance a
    // body's. The kernel between the cells the points touch (each once: neighbouring points share
    // cells), then summed over each pair of points' taps.
    const double area = field.settings().cell * field.settings().cell;
    std::vector<std::size_t> touched, slot(m * taps);
    for (std::size_t tap = 0; tap < m * taps; ++tap) {
        const auto found = std::find(touched.begin(), touched.end(), contact.cells[tap]);
        slot[tap] = std::size_t(found - touched.begin());
        if (found == touched.end()) touched.push_back(contact.cells[tap]);
    }
    const std::size_t k = touched.size();
    std::vector<double> between(k * k), reach(m * k, 0.0);  // cell to cell; point to cell
    for (std::size_t x = 0; x < k; ++x)
        for (std::size_t y = 0; y < k; ++y) between[x * k + y] = kernel_[offset(touched[x], touched[y])];
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t t = 0; t < taps; ++t)
            for (std::size_t y = 0; y < k; ++y) reach[i * k + y] += weight(i * taps + t) * between[slot[i * taps + t] * k + y];
    std::vector<double> a(m * m), q(m);
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < m; ++j) {
            double sum = 0;
            for (std::size_t u = 0; u < taps; ++u) sum += weight(j * taps + u) * reach[i * k + slot[j * taps + u]];
            a[i * m + j] = -sum / area + contact.compliance[i * m + j];
        }
        double felt = 0;
        for (std::size_t t = 0; t < taps; ++t) felt += weight(i * taps + t) * field.heights()[contact.cells[i * taps + t]];
        q[i] = felt - contact.target[i];
    }
    if (contact.push_only)
        q = solve_pushing(a, q);
    else
        solve_symmetric(a, q, m);
    // The pressure p / rho the pushes put on each cell, and its waves added to the free step's: the
    // same step of the same grid, from rest, with that pressure alone (the layer damps both alike).
    pressure_.assign(field.heights().size(), 0.0);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t t = 0; t < taps; ++t) pressure_[contact.cells[i * taps + t]] += weight(i * taps + t) * q[i] / area;
    if (!at_rest_ || !step08::same_grid(at_rest_->settings(), field.settings()) ||
        at_rest_->settings().absorbing_width != field.settings().absorbing_width ||
        at_rest_->settings().absorbing_rate != field.settings().absorbing_rate)
        at_rest_ = std::make_unique<WaveField>(field.settings());
    std::fill(at_rest_->heights().begin(), at_rest_->heights().end(), 0.0);
    std::fill(at_rest_->potentials().begin(), at_rest_->potentials().end(), 0.0);
    Forcing pushes;
    pushes.pressure = pressure_;
    at_rest_->step(dt, pushes);
    for (std::size_t c = 0; c < pressure_.size(); ++c) {
        field.heights()[c] += at_rest_->heights()[c];
        field.potentials()[c] += at_rest_->potentials()[c];
    }
    return q;
}

}  // namespace step09
