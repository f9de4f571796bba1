#include "step05_fft/spectrum.hpp"

#include "step05_fft/donelan_banner.hpp"
#include "step05_fft/mode_amplitude.hpp"

#include <algorithm>
#include <cmath>

namespace step05 {

double dispersion(double k, double depth) { return std::sqrt(kGravity * k * std::tanh(k * depth)); }

double dispersion_derivative(double k, double depth) {
    const double omega = dispersion(k, depth);
    if (omega <= 0) return std::sqrt(kGravity * depth) ;  // shallow-water limit as k -> 0
    const double kh = std::min(k * depth, 350.0);         // cosh overflows past ~710
    const double sech = 1.0 / std::cosh(kh);
    return kGravity * (std::tanh(kh) + kh * sech * sech) / (2.0 * omega);
}

double fully_developed_fetch(double wind_speed) {
    return kFullyDevelopedFetch * wind_speed * wind_speed / kGravity;
}

double developing_fetch(double wind_speed, double fetch) {
    return std::min(fetch, fully_developed_fetch(wind_speed));
}

double jonswap_alpha(double wind_speed, double fetch) {
    const double f = developing_fetch(wind_speed, fetch);
    return 0.076 * std::pow(wind_speed * wind_speed / (f * kGravity), 0.22);
}

double jonswap_peak_omega(double wind_speed, double fetch) {
    return 22.0 * std::cbrt(kGravity * kGravity / (wind_speed * developing_fetch(wind_speed, fetch)));
}

double jonswap(double omega, double wind_speed, double fetch, double gamma) {
    if (omega <= 0 || wind_speed <= 0 || fetch <= 0) return 0;
    const JonswapShape shape = jonswap_shape_for(wind_speed, fetch, gamma, JonswapEnergy::Fitted);
    return jonswap_with_alpha(omega, shape.alpha, jonswap_peak_omega(wind_speed, fetch), shape.gamma);
}

double pierson_moskowitz_peak_omega(double wind_speed) { return wind_speed > 0 ? 0.855 * kGravity / wind_speed : 0; }

double pierson_moskowitz_variance(double wind_speed) {
    if (wind_speed <= 0) return 0;
    return kPiersonMoskowitzAlpha * kGravity * kGravity /
           (5 * std::pow(pierson_moskowitz_peak_omega(wind_speed), 4));
}

double pierson_moskowitz(double omega, double wind_speed) {
    if (wind_speed <= 0) return 0;
    return jonswap_with_alpha(omega, kPiersonMoskowitzAlpha, pierson_moskowitz_peak_omega(wind_speed), 1.0);
}

double jonswap_with_alpha(double omega, double alpha, double peak, double gamma) {
    if (omega <= 0 || peak <= 0) return 0;
    const double sigma = omega <= peak ? 0.07 : 0.09;
    const double r = std::exp(-(omega - peak) * (omega - peak) / (2 * sigma * sigma * peak * peak));
    return alpha * kGravity * kGravity / std::pow(omega, 5) * std::exp(-1.25 * std::pow(peak / omega, 4)) *
           std::pow(gamma, r);
}

double jonswap_variance_per_alpha(double peak_omega, double gamma) {
    if (peak_omega <= 0) return 0;
    // In u = omega / omega_p the integrand is g^2 omega_p^-4 u^-5 exp(-5/4 u^-4) gamma^r(u).
    // Pierson-Moskowitz's part (gamma 1) integrates to g^2 / 5 exactly (substitute u^-4); gamma's
    // bump adds u^-5 exp(-5/4 u^-4) (gamma^r - 1), which lives within 0.3 < u < 2 (r < e^-50
    // beyond), where the midpoint rule sums it (4000 steps of 4e-4 against sigma >= 0.07: 1e-6 of
    // the bump). Cheap enough for the energy cap to search gamma with.
    const int steps = 4000;
    const double u0 = 0.3, u1 = 2.0, du = (u1 - u0) / steps;
    double bump = 0;
    for (int i = 0; i < steps; ++i) {
        const double u = u0 + (i + 0.5) * du;
        bump += jonswap_with_alpha(u, 1.0, 1.0, gamma) - jonswap_with_alpha(u, 1.0, 1.0, 1.0);
    }
    return (kGravity * kGravity / 5 + bump * du) / std::pow(peak_omega, 4);
}

double growth_law_variance(double wind_speed, double fetch) {
    if (wind_speed <= 0 || fetch <= 0) return 0;
    const double u2 = wind_speed * wind_speed;
    return 1.6e-7 * (kGravity * developing_fetch(wind_speed, fetch) / u2) * u2 * u2 / (kGravity * kGravity);
}

double cem_significant_height(double wind_speed, double fetch) {
    if (wind_speed <= 0 || fetch <= 0) return 0;
    const double friction2 = 0.001 * (1.1 + 0.035 * wind_speed) * wind_speed * wind_speed;  // u*^2
    return 4.13e-2 * std::sqrt(kGravity * fetch / friction2) * friction2 / kGravity;
}

namespace {

// jonswap_variance_per_alpha at omega_p = 1 rad/s; at any other peak it is this times omega_p^-4.
double unit_variance(double gamma) { return jonswap_variance_per_alpha(1.0, gamma); }

JonswapShape shape_without_cache(double wind_speed, double fetch, double gamma, JonswapEnergy energy) {
    const double peak4 = std::pow(jonswap_peak_omega(wind_speed, fetch), 4), per_alpha = unit_variance(gamma);
    const double alpha = energy == JonswapEnergy::Fitted
                             ? jonswap_alpha(wind_speed, fetch)
                             : growth_law_variance(wind_speed, fetch) * peak4 / per_alpha;
    // alpha * unit_variance(gamma) / omega_p^4 is the variance: it may not pass PM's.
    const double most = pierson_moskowitz_variance(wind_speed) * peak4;
    if (alpha * per_alpha <= most) return {alpha, gamma};
    // Too much energy. The peak's enhancement goes first: it is a young sea's overshoot, which the
    // fully developed sea (gamma 1) has lost. Bisection on gamma in [1, gamma]: the variance grows
    // with gamma.
    if (alpha * unit_variance(1.0) <= most) {
        double lo = 1.0, hi = gamma;
        for (int i = 0; i < 24; ++i) {
            const double mid = 0.5 * (lo + hi);
            (alpha * unit_variance(mid) <= most ? lo : hi) = mid;
        }
        return {alpha, lo};
    }
    // Then alpha, to PM's variance with gamma 1: at the fully developed fetch, where omega_p is
    // PM's, that is PM's own alpha, 0.0081 (unit_variance(1) = g^2 / 5).
    return {most / unit_variance(1.0), 1.0};
}

}  // namespace

JonswapShape jonswap_shape_for(double wind_speed, double fetch, double gamma, JonswapEnergy energy) {
    if (wind_speed <= 0 || fetch <= 0) return {0.0, gamma};
    // A few milliseconds (more where gamma is searched), and the spectrum asks once per mode:
    // keep the last answer (per thread, so spectra made in parallel stay correct).
    thread_local double last_wind = -1, last_fetch = -1, last_gamma = -1;
    thread_local JonswapEnergy last_energy = JonswapEnergy::Fitted;
    thread_local JonswapShape last;
    if (wind_speed != last_wind || fetch != last_fetch || gamma != last_gamma || energy != last_energy) {
        last = shape_without_cache(wind_speed, fetch, gamma, energy);
        last_wind = wind_speed, last_fetch = fetch, last_gamma = gamma, last_energy = energy;
    }
    return last;
}

double phillips_k(double k, double wind_speed) {
    if (k <= 0 || wind_speed <= 0) return 0;
    const double largest = wind_speed * wind_speed / kGravity;  // L: the longest wave the wind makes
    return 0.5 * 0.0081 * std::exp(-1.0 / (k * largest * k * largest)) / (k * k * k);
}

double tma_attenuation(double omega, double depth) {
    const double omega_h = omega * std::sqrt(depth / kGravity);
    if (omega_h <= 1) return 0.5 * omega_h * omega_h;
    if (omega_h < 2) return 1 - 0.5 * (2 - omega_h) * (2 - omega_h);
    return 1;
}

double spreading_exponent(double omega, double peak_omega, double wind_speed, double swell) {
    if (omega <= 0 || peak_omega <= 0) return 0;
    const double ratio = omega / peak_omega;
    // Above the peak the exponent falls faster for a young sea (U omega_p / g large).
    const double mu = -2.33 - 1.45 * (wind_speed * peak_omega / kGravity - 1.17);
    const double hasselmann = ratio <= 1 ? 6.97 * std::pow(ratio, 4.06) : 9.77 * std::pow(ratio, mu);
    // Horvath's swell term: long waves (omega < omega_p) narrow the most.
    return hasselmann + 16.0 * std::tanh(peak_omega / omega) * swell * swell;
}

double cos2s_spreading(double theta, double s) {
    // Normalisation of cos^2s(theta/2) over [-pi, pi]: Gamma(s+1)^2 2^(2s-1) / (pi Gamma(2s+1)).
    const double log_norm = 2 * std::lgamma(s + 1) - std::lgamma(2 * s + 1) + (2 * s - 1) * std::log(2.0) -
                            std::log(kPi);
    return std::exp(log_norm) * std::pow(std::abs(std::cos(0.5 * theta)), 2 * s);
}

double directional_spreading(double omega, double theta, double peak_omega, double wind_speed, double spread,
                             double swell, Spreading spreading) {
    if (spreading == Spreading::DonelanBanner && omega > 0 && peak_omega > 0)
        return spread / (2 * kPi) + (1 - spread) * sech2_spreading(theta, donelan_banner_beta(omega, peak_omega));
    const double s = spreading_exponent(omega, peak_omega, wind_speed, swell);
    return spread / (2 * kPi) + (1 - spread) * cos2s_spreading(theta, s);
}


double peak_omega_of(const SpectrumParams& p) {
    if (p.wind_speed <= 0) return 0;
    if (p.model == SpectrumModel::Jonswap) return jonswap_peak_omega(p.wind_speed, p.fetch);
    return std::pow(0.8, 0.25) * kGravity / p.wind_speed;  // where Phillips' S(omega) peaks
}

double omnidirectional_k(const SpectrumParams& p, double k) {
    if (k <= 0) return 0;
    const double omega = dispersion(k, p.depth);
    double density = 0;
    if (p.model == SpectrumModel::Jonswap) {
        if (p.wind_speed <= 0 || p.fetch <= 0) return 0;
        const JonswapShape shape = jonswap_shape_for(p.wind_speed, p.fetch, p.gamma, p.energy);
        density =
            jonswap_with_alpha(omega, shape.alpha, jonswap_peak_omega(p.wind_speed, p.fetch), shape.gamma) *
            dispersion_derivative(k, p.depth);
    } else {
        density = phillips_k(k, p.wind_speed);
    }
    if (p.tma) density *= tma_attenuation(omega, p.depth);
    return density;
}

double swell_spectrum(double omega, double height, double period) {
    if (height <= 0 || period <= 0 || omega <= 0) return 0;
    const double peak = 2 * kPi / period;
    // The integral of the unit-alpha shape depends on the peak only: computed once per period.
    thread_local double last_peak = -1, last_integral = 0;
    if (peak != last_peak) {
        last_peak = peak;
        last_integral = jonswap_variance_per_alpha(peak, kSwellGamma);
    }
    return height * height / 16.0 * jonswap_with_alpha(omega, 1.0, peak, kSwellGamma) / last_integral;
}

double swell_2d(const SpectrumParams& p, double kx, double kz) {
    const double k = std::hypot(kx, kz);
    if (k <= 0 || p.swell_height <= 0) return 0;
    const double theta = std::remainder(std::atan2(kz, kx) - p.swell_direction * kPi / 180.0, 2 * kPi);
    const double omega = dispersion(k, p.depth);
    const double d = cos2s_spreading(theta, p.swell_spreading);
    double density = swell_spectrum(omega, p.swell_height, p.swell_period) * dispersion_derivative(k, p.depth);
    if (p.tma) density *= tma_attenuation(omega, p.depth);
    return density * d / k;
}

double spectrum_2d(const SpectrumParams& p, double kx, double kz) {
    const double k = std::hypot(kx, kz);
    if (k <= 0 || k < p.low_cutoff || k >= p.high_cutoff) return 0;
    double wind_sea = 0;
    if (p.wind_speed > 0) {
        const double wind = p.wind_direction * kPi / 180.0;
        const double theta = std::remainder(std::atan2(kz, kx) - wind, 2 * kPi);  // into [-pi, pi]
        const double omega = dispersion(k, p.depth);
        const double d =
            directional_spreading(omega, theta, peak_omega_of(p), p.wind_speed, p.spread, p.swell, p.spreading);
        wind_sea = omnidirectional_k(p, k) * d / k;
    }
    return p.amplitude_scale * p.amplitude_scale * (wind_sea + swell_2d(p, kx, kz));
}

double wavenumber(int index, int n, double patch_size) {
    const int m = index < n / 2 ? index : index - n;
    return 2 * kPi * m / patch_size;
}

bool resolved_mode(const SpectrumParams& p, int i, int j) {
    const int n = p.resolution;
    if ((i == 0 && j == 0) || i == n / 2 || j == n / 2) return false;
    const double k = std::hypot(wavenumber(i, n, p.patch_size), wavenumber(j, n, p.patch_size));
    return k >= p.low_cutoff && k < p.high_cutoff;
}

double GaussianRandom::uniform() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double(z >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // (0, 1): log() stays finite
}

double GaussianRandom::next() {
    if (has_spare_) {
        has_spare_ = false;
        return spare_;
    }
    const double radius = std::sqrt(-2 * std::log(uniform()));
    const double angle = 2 * kPi * uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
}

InitialSpectrum initial_spectrum(const SpectrumParams& p) {
    const int n = p.resolution;
    const double dk = 2 * kPi / p.patch_size;
    InitialSpectrum s;
    s.n = n;
    s.patch_size = p.patch_size;
    s.h0.assign(std::size_t(n) * n, {0, 0});
    s.omega.assign(std::size_t(n) * n, 0);
    s.density.assign(std::size_t(n) * n, 0);
    GaussianRandom random(p.seed);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t index = std::size_t(j) * n + i;
            const double kx = wavenumber(i, n, p.patch_size), kz = wavenumber(j, n, p.patch_size);
            // Draw for every mode, resolved or not, so that changing a cut-off does not reshuffle
            // the random numbers of the modes that stay.
            const double xr = random.next(), xi = random.next();
            s.omega[index] = dispersion(std::hypot(kx, kz), p.depth);
            if (!resolved_mode(p, i, j)) continue;
            s.density[index] = spectrum_2d(p, kx, kz) * dk * dk;
            s.h0[index] = initial_amplitude(xr, xi, s.density[index]);
        }
    return s;
}

double resolved_variance(const SpectrumParams& p) { return resolved_moment(p, 0); }

double largest_displacement(double height_variance, double choppiness) {
    return 5 * std::sqrt(height_variance) * (1 + choppiness) + 1;
}

double resolved_slope_variance(const SpectrumParams& p) { return resolved_moment(p, 2); }

double resolved_moment(const SpectrumParams& p, int power) {
    double sum = 0;
    for_each_resolved_mode(p, [&](double kx, double kz, double energy) {
        sum += std::pow(kx * kx + kz * kz, 0.5 * power) * energy;
    });
    return sum;
}

std::vector<double> unresolved_slope_variance_by_level(const SpectrumParams& p) {
    const int levels = 1 + int(std::lround(std::log2(double(p.resolution))));
    const double texel = p.patch_size / p.resolution;
    std::vector<double> unresolved(std::size_t(levels), 0.0);
    const auto response = [&](double k, int level) {
        double h = 1;
        for (int j = 0; j < level; ++j) h *= std::cos(k * texel * double(1 << j) / 2);
        return h;
    };
    for_each_resolved_mode(p, [&](double kx, double kz, double energy) {
        const double variance = (kx * kx + kz * kz) * energy;
        for (int level = 1; level < levels; ++level) {
            const double kept = response(kx, level) * response(kz, level);
            unresolved[std::size_t(level)] += variance * (1 - kept * kept);
        }
    });
    return unresolved;
}

std::string validate(const SpectrumParams& p) {
    const int n = p.resolution;
    if (n < 64 || n > 512 || (n & (n - 1)) != 0)
        return "resolution must be a power of two in [64, 512], got " + std::to_string(n);
    if (!(p.patch_size > 0)) return "patch_size must be positive";
    if (!(p.depth > 0)) return "depth must be positive";
    if (!(p.fetch > 0)) return "fetch must be positive";
    if (p.low_cutoff > p.high_cutoff) return "low_cutoff must not exceed high_cutoff";
    return "";
}

}  // namespace step05
