// Donelan and Banner's directional spreading (Donelan, Hamilton and Hui 1985; Banner 1990, as
// Horvath 2015 writes it for rendering): the alternative to Hasselmann's cos^2s(theta / 2) that
// `--set spreading=donelan_banner` draws. Its lobe is sech^2(beta theta) about the wind, beta from
// the wave's frequency over the peak's:
//     beta = 2.61 (omega/omega_p)^1.3        for 0.56 < omega/omega_p < 0.95,
//     beta = 2.28 (omega/omega_p)^-1.3       for 0.95 <= omega/omega_p < 1.6,
//     beta = 10^eps, eps = -0.4 + 0.8393 exp(-0.567 ln((omega/omega_p)^2))   otherwise:
// narrowest at the peak (beta 2.28), wider above it, and beta falls towards 10^-0.4 = 0.40 for
// the short waves, whose lobe then reaches round to theta = +-pi (capped at 100 far below the peak).
#pragma once

namespace step05 {

double donelan_banner_beta(double omega, double peak_omega);
// sech^2(beta theta), normalised to integrate to 1 over theta in [-pi, pi] (beta > 0). Exercise 10
// (./ocean exercise step05_fft 10) empties it; tests/test_spectrum.cpp holds it to the midpoint rule.
double sech2_spreading(double theta, double beta);

}  // namespace step05
