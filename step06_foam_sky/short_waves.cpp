#include "step06_foam_sky/short_waves.hpp"

#include "step06_foam_sky/cascades.hpp"

#include <algorithm>
#include <cmath>

namespace step06 {

using step05::kGravity;
using step05::kPi;

SlopeVariance cox_munk(double wind_speed_10m) {
    const double u = wind_speed_10m * std::log(12.5 / kSeaRoughnessLength) / std::log(10 / kSeaRoughnessLength);
    return {3.16e-3 * u, 0.003 + 1.92e-3 * u};
}

double friction_velocity(double wind_speed_10m) {
    return std::sqrt((0.8 + 0.065 * wind_speed_10m) * 1e-3) * wind_speed_10m;
}

namespace {

// Deep-water phase speed with surface tension: c(k) = sqrt(g/k (1 + (k/k_m)^2)), which is c_m at k_m.
double phase_speed(double k) {
    const double r = k / kCapillaryWavenumber;
    return std::sqrt(kGravity / k * (1 + r * r));
}

}  // namespace

double short_wave_curvature(double k, double wind_speed_10m, double peak_k) {
    if (k <= 0 || wind_speed_10m <= 0) return 0;
    const double u_star = friction_velocity(wind_speed_10m);
    const double ratio = u_star / kMinimumPhaseSpeed;
    const double alpha_m = 0.01 * (ratio < 1 ? 1 + std::log(ratio) : 1 + 3 * std::log(ratio));
    const double shape = std::exp(-0.25 * (k / kCapillaryWavenumber - 1) * (k / kCapillaryWavenumber - 1));
    // L_PM: nothing below the peak. (Their J_p, the peak enhancement, is 1 this far above k_p.)
    const double below_peak = peak_k > 0 ? std::exp(-1.25 * (peak_k / k) * (peak_k / k)) : 1;
    return std::max(0.0, 0.5 * alpha_m * kMinimumPhaseSpeed / phase_speed(k) * shape * below_peak);
}

double spreading_delta(double k, double wind_speed_10m, double peak_k) {
    const double c = phase_speed(k);
    const double c_p = peak_k > 0 ? phase_speed(peak_k) : 1e30;
    const double a_m = 0.13 * friction_velocity(wind_speed_10m) / kMinimumPhaseSpeed;
    return std::tanh(std::log(2.0) / 4 + 4 * std::pow(c / c_p, 2.5) + a_m * std::pow(kMinimumPhaseSpeed / c, 2.5));
}

SlopeVariance short_wave_slope_variance(double wind_speed_10m, double peak_k, double from_k) {
    // The integral of B_h dk / k = B_h d(ln k), by the midpoint rule in ln k up to 100 k_m (the
    // capillary bump is gone by 20 k_m: exp(-90)).
    SlopeVariance v;
    const double top = 100 * kCapillaryWavenumber;
    if (from_k <= 0 || from_k >= top) return v;
    const int steps = 4000;
    const double step = std::log(top / from_k) / steps;
    for (int i = 0; i < steps; ++i) {
        const double k = from_k * std::exp((i + 0.5) * step);
        const double slope = short_wave_curvature(k, wind_speed_10m, peak_k) * step;
        const double delta = spreading_delta(k, wind_speed_10m, peak_k);
        // The mean of cos^2 phi (and sin^2 phi) over (1 + Delta cos 2 phi) / (2 pi).
        v.upwind += slope * 0.5 * (1 + 0.5 * delta);
        v.crosswind += slope * 0.5 * (1 - 0.5 * delta);
    }
    return v;
}

glm::dvec2 wind_heading(const step05::SpectrumParams& p) {
    const double angle = p.wind_direction * kPi / 180;
    return {std::cos(angle), std::sin(angle)};
}

SlopeVariance resolved_slope_variance_by_axis(const step05::SpectrumParams& p) {
    const glm::dvec2 wind = wind_heading(p);
    const double ux = wind.x, uz = wind.y;
    SlopeVariance v;
    step05::for_each_resolved_mode(p, [&](double kx, double kz, double energy) {
        const double along = kx * ux + kz * uz, across = -kx * uz + kz * ux;
        v.upwind += along * along * energy;
        v.crosswind += across * across * energy;
    });
    return v;
}

SlopeVariance short_wave_slope_variance_beyond(const step05::SpectrumParams& shared) {
    const double omega_p = step05::peak_omega_of(shared);
    const double peak_k = omega_p * omega_p / kGravity;
    const double scale = shared.amplitude_scale * shared.amplitude_scale;
    const double last_band_end = cascade_bands(cascade_patch_sizes(shared), shared.resolution).back().high;
    const SlopeVariance s = short_wave_slope_variance(shared.wind_speed, peak_k, std::min(last_band_end, shared.high_cutoff));
    return {s.upwind * scale, s.crosswind * scale};
}

SlopeVariance sea_slope_variance(const step05::SpectrumParams& shared) {
    SlopeVariance v = short_wave_slope_variance_beyond(shared);
    for (const auto& p : cascade_spectra(shared)) {
        const SlopeVariance c = resolved_slope_variance_by_axis(p);
        v.upwind += c.upwind;
        v.crosswind += c.crosswind;
    }
    return v;
}

}  // namespace step06
