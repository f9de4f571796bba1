// physics_check: what a viewer would check, measured from what a step exported (--export), not
// from the code's own reference. It knows nothing of the spectrum or the shaders: it reads PFM
// maps and export.txt.
//
//   physics_check travel DIR_A DIR_B DEGREES TOLERANCE
//       two exports of the same sea at times t_A < t_B: the direction the waves travel, from the
//       phase motion of the height field, must be DEGREES within TOLERANCE. On a periodic tile
//       (step05) every Fourier mode k moves its phase by -omega dt, a velocity -(dphase/dt)/|k|
//       along k/|k|; their mean weighted by the mode's energy is the sea's direction of travel.
//       On a window of the summed, non-periodic surface (step06) the same is measured as an
//       optical flow: the velocity v that best explains dh/dt = -v . grad h (least squares).
//   physics_check crests DIR
//       corr(height, Jacobian) must be negative (the surface squeezes, J < 1, at the crests: sharp
//       crests, not sharp troughs), and where DIR has foam.pfm, corr(foam, height) positive (foam
//       on the crests).
// (What only one chapter's sea is held to lives with that chapter: step06's whitecaps and far sea
// in step06_foam_sky/tests/sea_check.cpp.)
// Prints the figures; exit 0 when they hold, 1 otherwise (and 2 on bad input).
#include "step05_fft/ocean_maps.hpp"
#include "tests/export_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using ocean_test::Export;
using ocean_test::read_export;

constexpr double kPi = 3.14159265358979323846;

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / double(a.size()), mb += b[i] / double(b.size());
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0.0;
}

// Energy-weighted phase velocity of a periodic tile's Fourier modes (m/s, x and z).
std::pair<double, double> fourier_velocity(const std::vector<double>& h1, const std::vector<double>& h2, int n,
                                           double extent, double dt) {
    // For a real field the forward transform is the conjugate of the inverse one.
    auto forward = [n](const std::vector<double>& h) {
        step05::ComplexField field(h.begin(), h.end());
        auto out = step05::inverse_fft_2d(field, n);
        for (auto& v : out) v = std::conj(v);
        return out;
    };
    const auto a = forward(h1), b = forward(h2);
    double vx = 0, vz = 0, weight = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i == 0 && j == 0) || i == n / 2 || j == n / 2) continue;
            const double kx = step05::wavenumber(i, n, extent), kz = step05::wavenumber(j, n, extent);
            const double k = std::hypot(kx, kz);
            const std::size_t index = std::size_t(j) * n + i;
            const double dphase = std::arg(b[index] * std::conj(a[index]));  // in (-pi, pi]
            const double energy = std::abs(a[index]) * std::abs(b[index]);
            const double speed = -dphase / dt / k;  // along k/|k|
            vx += energy * speed * kx / k;
            vz += energy * speed * kz / k;
            weight += energy;
        }
    return {vx / weight, vz / weight};
}

// Least-squares optical flow of a height field on a grid (interior cells): dh/dt = -v . grad h.
std::pair<double, double> flow_velocity(const std::vector<double>& h1, const std::vector<double>& h2, int n,
                                        double spacing, double dt) {
    double mxx = 0, mxz = 0, mzz = 0, bx = 0, bz = 0;
    auto at = [n](const std::vector<double>& h, int i, int j) { return h[std::size_t(j) * n + i]; };
    for (int j = 1; j < n - 1; ++j)
        for (int i = 1; i < n - 1; ++i) {
            const double gx = (at(h1, i + 1, j) - at(h1, i - 1, j) + at(h2, i + 1, j) - at(h2, i - 1, j)) / (4 * spacing);
            const double gz = (at(h1, i, j + 1) - at(h1, i, j - 1) + at(h2, i, j + 1) - at(h2, i, j - 1)) / (4 * spacing);
            const double dh = (at(h2, i, j) - at(h1, i, j)) / dt;
            mxx += gx * gx, mxz += gx * gz, mzz += gz * gz;
            bx += gx * dh, bz += gz * dh;
        }
    const double det = mxx * mzz - mxz * mxz;
    // v = -M^-1 b
    return {-(mzz * bx - mxz * bz) / det, -(-mxz * bx + mxx * bz) / det};
}

int travel(const std::string& dir_a, const std::string& dir_b, double expected_deg, double tolerance_deg) {
    const Export a = read_export(dir_a), b = read_export(dir_b);
    if (a.n != b.n || a.extent != b.extent || !(b.time > a.time))
        throw std::runtime_error("the two exports must share their grid, the second one later");
    if (!a.periodic && (a.values.at("export.origin_x") != b.values.at("export.origin_x") ||
                        a.values.at("export.origin_z") != b.values.at("export.origin_z")))
        throw std::runtime_error("the two exports' windows differ: keep the camera still");
    const auto h1 = a.map(dir_a, "height.pfm"), h2 = b.map(dir_b, "height.pfm");
    const double dt = b.time - a.time;
    const auto [vx, vz] = a.periodic ? fourier_velocity(h1, h2, a.n, a.extent, dt)
                                     : flow_velocity(h1, h2, a.n, a.extent / a.n, dt);
    const double measured = std::fmod(std::atan2(vz, vx) * 180 / kPi + 360.0, 360.0);
    const double error = std::abs(std::remainder(measured - expected_deg, 360.0));
    std::printf("direction of travel: %.1f degrees (%s, %.2f m/s), expected %.1f: off by %.1f (tolerance %.1f)\n",
                measured, a.periodic ? "energy-weighted phase motion" : "least-squares flow", std::hypot(vx, vz),
                expected_deg, error, tolerance_deg);
    return error <= tolerance_deg ? 0 : 1;
}

int crests(const std::string& dir) {
    const Export e = read_export(dir);
    const auto height = e.map(dir, "height.pfm"), jacobian = e.map(dir, "jacobian.pfm");
    const double h_j = correlation(height, jacobian);
    double below = 0;
    for (double j : jacobian) below += j < 1;
    std::printf("corr(height, J) = %+.3f (J < 1 on %.1f %% of the grid)\n", h_j, 100 * below / double(jacobian.size()));
    int failures = h_j < 0 ? 0 : 1;
    if (e.values.count("file.foam")) {
        const auto foam = e.map(dir, e.values.at("file.foam"));
        const double f_h = correlation(foam, height), f_j = correlation(foam, jacobian);
        double covered = 0;
        for (double f : foam) covered += f > 0.05;
        std::printf("corr(foam, height) = %+.3f, corr(foam, J) = %+.3f, foam > 0.05 on %.2f %% of the grid\n", f_h,
                    f_j, 100 * covered / double(foam.size()));
        failures += f_h > 0 ? 0 : 1;
        failures += f_j < 0 ? 0 : 1;  // view=foam and view=jacobian agree: foam where J is low
        if (covered == 0) std::printf("no foam at all: nothing to check it against\n"), ++failures;
    }
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "travel" && argc == 6) return travel(argv[2], argv[3], std::stod(argv[4]), std::stod(argv[5]));
        if (mode == "crests" && argc == 3) return crests(argv[2]);
        std::fprintf(stderr, "usage: physics_check travel DIR_A DIR_B DEGREES TOLERANCE | crests DIR\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "physics_check: %s\n", e.what());
        return 2;
    }
}
