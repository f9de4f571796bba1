// The sea's slopes as the sun's glitter measures them, on the CPU in double precision: the waves
// the cascades simulate, plus the waves shorter than the finest cascade down to the capillaries,
// which no grid holds but which carry most of the slope variance the glitter sees.
//
// Cox and Munk (1954) measured the mean square slope of a clean sea from aerial photographs of the
// sun's glitter: upwind 3.16e-3 U, crosswind 0.003 + 1.92e-3 U (U in m/s at 12.5 m; total
// 0.003 + 5.12e-3 U +- 0.004). The short waves come from Elfouhaily, Chapron, Katsaros and Vandemark
// (1997), "A unified directional spectrum for long and short wind-driven waves", whose short-wave
// curvature B_h(k) and spreading Delta(k) were fitted to the same observations among others; the
// sum is held to Cox and Munk in the tests (how_we_know.md), not fitted to them here.
#pragma once

#include "step05_fft/spectrum.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step06 {

// The unit vector (x, z) the wind blows towards, from p.wind_direction (degrees, 0 = +x, 90 = +z).
glm::dvec2 wind_heading(const step05::SpectrumParams& p);

// Slope variance along the wind and across it, E[(dh/du)^2] and E[(dh/dc)^2] (dimensionless).
struct SlopeVariance {
    double upwind = 0, crosswind = 0;
    double total() const { return upwind + crosswind; }
};

// Cox and Munk's clean-sea fit, for the wind at 10 m (converted to their 12.5 m on a logarithmic
// profile over a sea of roughness length kSeaRoughnessLength).
constexpr double kSeaRoughnessLength = 2e-4;  // metres: open sea, moderate wind
SlopeVariance cox_munk(double wind_speed_10m);

// u*, m/s: sqrt(C_D) U10 with Wu's (1982) drag coefficient C_D = (0.8 + 0.065 U10) 1e-3.
double friction_velocity(double wind_speed_10m);

// Elfouhaily et al.'s short-wave curvature B_h(k) = k^3 S(k) (dimensionless), for a sea whose peak
// is at wavenumber k_p: alpha_m / 2 (c_m / c) exp(-(k/k_m - 1)^2 / 4) L_PM J_p, with the gravity-
// capillary minimum phase speed c_m = 0.23 m/s at k_m = 370 rad/m, c(k) = sqrt(g/k (1 + (k/k_m)^2)),
// and alpha_m = 0.01 (1 + ln(u*/c_m)) below u* = c_m, 0.01 (1 + 3 ln(u*/c_m)) above.
constexpr double kMinimumPhaseSpeed = 0.23;       // c_m, m/s
constexpr double kCapillaryWavenumber = 370;      // k_m, rad/m (a 1.7 cm wave)
double short_wave_curvature(double k, double wind_speed_10m, double peak_k);
// Their spreading: Phi(k, phi) = S(k)/k (1 + Delta(k) cos 2 phi) / (2 pi), with
// Delta = tanh(ln 2 / 4 + 4 (c/c_p)^2.5 + 0.13 (u*/c_m) (c_m/c)^2.5): short waves spread more widely
// than the peak but still favour the wind.
double spreading_delta(double k, double wind_speed_10m, double peak_k);

// The slope variance of the short waves from `from_k` (the finest cascade's last wavenumber) up:
// the integral of B_h(k) dk / k, split along and across the wind by (1 +- Delta/2) / 2.
SlopeVariance short_wave_slope_variance(double wind_speed_10m, double peak_k, double from_k);

// The simulated spectra's slope variance along and across `p.wind_direction`: sum over the resolved
// modes of (k.u)^2 Phi dk^2 and (k.c)^2 Phi dk^2 (both cascades' bands and the swell included).
SlopeVariance resolved_slope_variance_by_axis(const step05::SpectrumParams& p);

// The short waves beyond the last of step06's cascades made from `shared` (amplitude_scale applied).
SlopeVariance short_wave_slope_variance_beyond(const step05::SpectrumParams& shared);
// Everything the glitter sees for step06's cascades made from `shared`: the four cascades' resolved
// slopes plus the short waves beyond the last band.
SlopeVariance sea_slope_variance(const step05::SpectrumParams& shared);

}  // namespace step06
