#include "step05_fft/donelan_banner.hpp"

#include "common/constants.hpp"

#include <algorithm>
#include <cmath>

namespace step05 {

double donelan_banner_beta(double omega, double peak_omega) {
    const double ratio = omega / peak_omega;
    if (ratio > 0.56 && ratio < 0.95) return 2.61 * std::pow(ratio, 1.3);
    if (ratio >= 0.95 && ratio < 1.6) return 2.28 * std::pow(ratio, -1.3);
    // Far below the peak (a long wave of a young sea) 10^eps grows without bound: capped at 100, a
    // lobe under a degree wide, so that it stays a number.
    return std::min(100.0, std::pow(10.0, -0.4 + 0.8393 * std::exp(-0.567 * std::log(ratio * ratio))));
}

double sech2_spreading(double theta, double beta) {
    // The integral of sech^2(beta theta) is tanh(beta theta) / beta: over [-pi, pi], 2 tanh(beta pi) /
    // beta, a little less than the whole line's 2 / beta where the lobe is wide.
    const double sech = 1 / std::cosh(beta * theta);
    return beta / (2 * std::tanh(beta * ocean::kPi)) * sech * sech;
}

}  // namespace step05
