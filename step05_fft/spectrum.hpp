// Chapter 4.1 on the CPU, in double precision: the ocean's wave spectrum and the initial
// amplitudes h0(k) drawn from it. The GPU receives h0 and omega from here (they are computed
// once, and again when a parameter changes); tests hold the GPU's transforms to this reference.
//
// From a 1D frequency spectrum S(omega) (JONSWAP) and a directional spreading D(omega, theta)
// with integral over theta = 1, the 2D spectrum over wavenumbers is
//     Phi(kx, kz) = S(omega(k)) * D(omega, theta) * (d omega / dk) / k
// because S domega dtheta = Phi dkx dkz and dkx dkz = k dk dtheta. Its integral over all k is
// the variance of the sea surface, in m^2, when amplitude_scale = 1.
#pragma once

#include "common/constants.hpp"

#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace step05 {

using ocean::kGravity;
using ocean::kPi;

enum class SpectrumModel { Jonswap = 0, Phillips = 1 };
// JONSWAP's alpha and omega_p come from two separate fits to the 1973 data, and together they
// overestimate the energy of a fetch-limited sea (README, "Heights against observations").
// GrowthLaw keeps the shape and scales alpha so that the variance follows JONSWAP's own growth
// law E g^2 / U^4 = 1.6e-7 g F / U^2.
enum class JonswapEnergy { Fitted = 0, GrowthLaw = 1 };
// The wind sea's directional lobe: Hasselmann's cos^2s(theta / 2) (below), or Donelan and Banner's
// sech^2(beta theta) (donelan_banner.hpp).
enum class Spreading { Hasselmann = 0, DonelanBanner = 1 };

struct SpectrumParams {
    SpectrumModel model = SpectrumModel::Jonswap;
    double wind_speed = 9;         // U, m/s at 10 m
    double wind_direction = 30;    // degrees, direction the wind blows towards (0 = +x, 90 = +z)
    double fetch = 100000;         // F, metres of open water upwind
    double gamma = 3.3;            // JONSWAP peak enhancement
    JonswapEnergy energy = JonswapEnergy::Fitted;
    double spread = 0.2;           // fraction of the energy spread evenly over all directions
    double swell = 0;              // 0..1: narrows the spreading around the wind (long-crested swell)
    Spreading spreading = Spreading::Hasselmann;  // the wind sea's lobe (swell narrows Hasselmann's only)
    // A swell from a distant storm, added to the wind sea (swell_spectrum below): its own height,
    // peak period, direction and spreading. swell_height = 0: no swell.
    double swell_height = 0;       // Hs of the swell alone, metres
    double swell_period = 12;      // peak period, seconds
    double swell_direction = 120;  // degrees, where the swell travels (0 = +x, 90 = +z)
    double swell_spreading = 24;   // s of cos^2s((theta - direction) / 2): larger is longer-crested
    double depth = 500;            // metres (finite-depth dispersion; TMA attenuation when enabled)
    bool tma = false;              // TMA shallow-water attenuation of the spectrum
    double patch_size = 250;       // L, metres: the simulated tile repeats every L
    int resolution = 256;          // N x N modes
    std::uint64_t seed = 1;
    double amplitude_scale = 1;    // 1: heights in metres
    double low_cutoff = 0;         // rad/m: the band kept is low_cutoff <= |k| < high_cutoff, so
    double high_cutoff = 1000;     // that bands cut from one spectrum (cascades) share a boundary without overlap
};

// The finite-depth dispersion relation omega^2 = g k tanh(k h), and its derivative. Used alike
// by the spectrum and by the time evolution.
double dispersion(double k, double depth);
double dispersion_derivative(double k, double depth);  // d omega / dk

// The fully developed sea caps the fetch. JONSWAP's peak, written with the dimensionless fetch
// F~ = g F / U^2, is 22 (g^2 / (U F))^(1/3) = 22 (g / U) F~^(-1/3): it falls as the fetch grows,
// and reaches Pierson-Moskowitz's 0.855 g / U (below) where F~^(1/3) = 22 / 0.855, at
//     F~_fd = (22 / 0.855)^3 = 1.7036e4        (174 km at 10 m/s, 841 km at 22 m/s).
// Past that the wind has given the sea all it can and it grows no more (the cap Horvath 2015
// puts on JONSWAP's fetch): the fetch the spectrum uses is min(F, F~_fd U^2 / g).
constexpr double kFullyDevelopedFetch = (22 / 0.855) * (22 / 0.855) * (22 / 0.855);  // g F / U^2
double fully_developed_fetch(double wind_speed);           // metres: kFullyDevelopedFetch U^2 / g
double developing_fetch(double wind_speed, double fetch);  // min(fetch, fully_developed_fetch)
// JONSWAP's fetch-limited parameters, at the developing fetch F = developing_fetch(U, fetch).
double jonswap_alpha(double wind_speed, double fetch);        // 0.076 (U^2 / (F g))^0.22
double jonswap_peak_omega(double wind_speed, double fetch);   // 22 (g^2 / (U F))^(1/3)
// S(omega), m^2 s / rad, with a given alpha (the fit's, or the growth law's). Zero for omega <= 0
// or a calm sea. With gamma = 1 it is the Pierson-Moskowitz shape, whose integral is
// alpha g^2 / (5 omega_p^4). jonswap() is the spectrum as fitted, capped as the sea uses it
// (alpha and gamma from jonswap_shape_for with JonswapEnergy::Fitted).
double jonswap(double omega, double wind_speed, double fetch, double gamma);
double jonswap_with_alpha(double omega, double alpha, double peak_omega, double gamma);
// Pierson-Moskowitz (1964): the fully developed sea, the limit of unlimited fetch and duration,
// S(omega) = alpha g^2 / omega^5 exp(-5/4 (omega_p / omega)^4) with alpha = 0.0081 and
// omega_p = 0.855 g / U. Its variance alpha g^2 / (5 omega_p^4) gives Hs = 0.22 U^2 / g. (JONSWAP
// with gamma = 1 has this shape, but its alpha and omega_p still depend on the fetch.)
constexpr double kPiersonMoskowitzAlpha = 0.0081;
double pierson_moskowitz_peak_omega(double wind_speed);  // 0.855 g / U
double pierson_moskowitz(double omega, double wind_speed);
// Its variance in closed form, alpha g^2 / (5 omega_p^4) = 3.03e-3 U^4 / g^2 (m^2): the most any
// wind sea of that wind holds. Hs = 4 sqrt of it = 0.2202 U^2 / g, the textbooks' 0.21 U19.5^2 / g
// with the wind at 19.5 m (U19.5 = 1.026 U10 on a log profile: Pierson and Moskowitz's 0.877 g /
// U19.5 is this 0.855 g / U10).
double pierson_moskowitz_variance(double wind_speed);
// The integral of S over omega for alpha = 1 (numerical: gamma's bump has no closed form).
double jonswap_variance_per_alpha(double peak_omega, double gamma);
// The alpha and gamma the wind sea uses under `energy`, at the developing fetch, holding at most
// Pierson-Moskowitz's variance. The fetch cap alone does not keep JONSWAP as fitted below it: its
// alpha and gamma's bump (x 1.52 at gamma 3.3) pass PM's variance already at F~ = 1.07e4 and
// hold 1.68 times it at F~_fd (alpha = 0.076 F~_fd^-0.22 = 0.0089; README, "Heights against
// observations"). Where the energy would pass PM's, gamma is lowered towards 1 (the peak's
// enhancement is a young sea's overshoot, which the fully developed sea has lost), then alpha;
// at F~_fd the fitted sea is PM's spectrum itself (alpha 0.0081, gamma 1). Lowering alpha alone
// there would drop the short waves' level to 0.0053, below PM's 0.0081, and with it the slopes a
// sun's glitter is held to (Cox & Munk's). Under the growth law the energy stays below PM's (0.90 of it at F~_fd).
struct JonswapShape {
    double alpha = 0;
    double gamma = 1;
};
JonswapShape jonswap_shape_for(double wind_speed, double fetch, double gamma, JonswapEnergy energy);

// Observed fetch-limited growth, for comparing the spectrum's heights with the sea's:
// JONSWAP's growth law (Hasselmann et al. 1973): E g^2 / U^4 = 1.6e-7 g F / U^2, Hs = 4 sqrt(E),
// at the developing fetch (a fully developed sea grows no more);
double growth_law_variance(double wind_speed, double fetch);
// the Coastal Engineering Manual (II-2, eq. II-2-36, deep water): g Hm0 / u*^2 = 4.13e-2
// (g F / u*^2)^(1/2) with u*^2 = C_D U^2, C_D = 0.001 (1.1 + 0.035 U). Metres.
double cem_significant_height(double wind_speed, double fetch);
// Phillips, corrected from the notes: F(k) = (alpha / 2) exp(-1 / (k L)^2) / k^3 per unit k, with
// L = U^2 / g and alpha = 0.0081; as a 2D density that is the notes' exp(-1/(kL)^2) / k^4 shape.
double phillips_k(double k, double wind_speed);
// Kitaigorodskii's depth attenuation used by the TMA spectrum (1 in deep water).
double tma_attenuation(double omega, double depth);

// Hasselmann's cos^2s exponent for omega relative to the peak, plus the swell's narrowing:
//   s = 6.97 (omega/omega_p)^4.06                                  below the peak,
//   s = 9.77 (omega/omega_p)^(-2.33 - 1.45 (U omega_p / g - 1.17))  above it (Hasselmann et al. 1980).
double spreading_exponent(double omega, double peak_omega, double wind_speed, double swell);
// N(s) cos^2s(theta / 2), normalised to integrate to 1 over [-pi, pi] (the wind sea's lobe and
// the swell's).
double cos2s_spreading(double theta, double s);
// D(omega, theta) with theta measured from the wind: integrates to 1 over [-pi, pi]. `spread` of it
// even over all directions, the rest in the lobe of `spreading`.
double directional_spreading(double omega, double theta, double peak_omega, double wind_speed, double spread,
                             double swell, Spreading spreading = Spreading::Hasselmann);

// The swell's S(omega): JONSWAP's shape around omega_s = 2 pi / swell_period with gamma =
// kSwellGamma (swell that has travelled far is narrow), scaled so that its integral is
// (swell_height / 4)^2: a swell is described by its height and period, not by a wind.
constexpr double kSwellGamma = 7;
double swell_spectrum(double omega, double height, double period);
// Phi of the swell alone at (kx, kz), with its cos^2s spreading (no cut-offs, no amplitude_scale).
double swell_2d(const SpectrumParams& p, double kx, double kz);

// The spectrum's peak angular frequency: JONSWAP's omega_p; for Phillips, where its S(omega) =
// F(k) dk/domega ~ omega^-5 exp(-(g/(U omega))^4) peaks: (4/5)^(1/4) g / U.
double peak_omega_of(const SpectrumParams& p);

// Energy density per unit k of the omnidirectional spectrum (m^2 per rad/m), for the model.
double omnidirectional_k(const SpectrumParams& p, double k);
// Phi(kx, kz), m^2 per (rad/m)^2: the wind sea plus the swell, including cut-offs and
// amplitude_scale^2.
double spectrum_2d(const SpectrumParams& p, double kx, double kz);

// Wavenumber of grid index i (FFT layout: 0..N/2-1, then -N/2..-1), rad/m.
double wavenumber(int index, int n, double patch_size);
// True for the modes the grid can carry as travelling waves: not k = 0, not the Nyquist row or
// column (which has no -k partner), inside the cut-offs.
bool resolved_mode(const SpectrumParams& p, int i, int j);

struct InitialSpectrum {
    int n = 0;
    double patch_size = 0;
    std::vector<std::complex<double>> h0;  // n*n, row j (z) major, FFT layout
    std::vector<double> omega;             // n*n, rad/s, from the dispersion relation
    std::vector<double> density;           // n*n, Phi(k) dk^2: the expected energy of each mode
};

// h0(k) = (xi_r + i xi_i) sqrt(Phi(k) dk^2 / 4) with xi standard normal. The 1/4 (not the
// notes' 1/2) because the time evolution adds conj(h0(-k)), a second copy of every mode's energy:
// then E|h(k, t)|^2 = (Phi(k) + Phi(-k)) dk^2 / 2 and the height variance is sum Phi dk^2.
InitialSpectrum initial_spectrum(const SpectrumParams& p);

// Calls visit(kx, kz, energy) for every resolved mode of p's grid, energy = Phi(k) dk^2 (m^2): the
// one loop every sum over the spectrum below is made of.
template <class Visit>
void for_each_resolved_mode(const SpectrumParams& p, Visit&& visit) {
    const int n = p.resolution;
    const double dk = 2 * kPi / p.patch_size;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (resolved_mode(p, i, j)) {
                const double kx = wavenumber(i, n, p.patch_size), kz = wavenumber(j, n, p.patch_size);
                visit(kx, kz, spectrum_2d(p, kx, kz) * dk * dk);
            }
}

// sum over resolved modes of Phi(k) dk^2: the expected variance of the height field, m^2.
double resolved_variance(const SpectrumParams& p);
// A bound on how far any point of the sea moves from rest, metres, for frustum culling (step05's
// grid chunks, or any mesh's patches): five standard deviations of the height, as much again times
// the choppiness sideways (|D~| = |h~| mode by mode), and a metre.
double largest_displacement(double height_variance, double choppiness);
// sum over resolved modes of |k|^2 Phi(k) dk^2: the expected variance of the slope, summed over
// both axes (E[(dh/dx)^2 + (dh/dz)^2]).
double resolved_slope_variance(const SpectrumParams& p);
// The slope variance each mip level of the slope maps averages away (Bruneton, Neyret and
// Holzschuch 2010: what a pixel cannot resolve becomes roughness, computed from the spectrum).
// Level l's texel is the mean of a 2^l x 2^l block of the map's texels, a filter whose response
// to a wave of wavenumber k along an axis is H_l(k) = prod_{j<l} cos(k d 2^j / 2) (d = L / N):
// so the expected slope variance left in level l is sum |k|^2 Phi H_l(kx)^2 H_l(kz)^2 dk^2, and
// entry l is the rest. Entry 0 is 0; entry log2(N), the 1 x 1 level, is resolved_slope_variance.
std::vector<double> unresolved_slope_variance_by_level(const SpectrumParams& p);
// sum over resolved modes of |k|^power Phi(k) dk^2.
double resolved_moment(const SpectrumParams& p, int power);

// Standard normal numbers from splitmix64 + Box-Muller: the same seed, the same sea, anywhere.
class GaussianRandom {
public:
    explicit GaussianRandom(std::uint64_t seed) : state_(seed) {}
    double next();

private:
    double uniform();
    std::uint64_t state_;
    bool has_spare_ = false;
    double spare_ = 0;
};


// A one-line problem with the parameters, or "" (resolution not a power of two in [64, 512]...).
std::string validate(const SpectrumParams& p);

}  // namespace step05
