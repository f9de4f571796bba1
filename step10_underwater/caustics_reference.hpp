// Chapter 10, caustics: the bright dancing lines on a shallow seabed. Each crest of a wave is a
// weak lens; sunlight refracted through it converges below, and where neighbouring rays cross
// the seabed gathers more light than it would under a flat sea. This is the reference the
// shader's caustics are held to: a 1D sea h(x) = a cos(k x), rays traced one by one on the CPU.
#pragma once

#include "common/constants.hpp"

#include <vector>

namespace step10 {

struct CausticSea {
    double amplitude = 0.05;    // a, metres
    double wavenumber = ocean::kPi;  // k, radians per metre: 2 m waves (wavelength 2 pi / k)
    double depth = 8;           // D, metres from the mean surface down to the flat seabed
    double sun_zenith = 0;      // radians from the vertical, in air, the sun towards -x (light going +x)
    int rays = 200000;          // over one wavelength of the sea, evenly spaced in x
    int bins = 200;             // seabed cells over one wavelength
};

// Irradiance on the seabed over one wavelength of the sea (the pattern repeats), relative to the
// sun's irradiance on a horizontal plane above the water: a flat sea would give 1 - R everywhere.
// Bin i covers x from i to i + 1 times wavelength / bins; x = 0 lies under a crest.
struct SeabedIrradiance {
    std::vector<double> irradiance;  // per bin, bins of equal width
    double mean() const;
    double peak() const;
    double peak_over_mean() const;
    double contrast() const;  // standard deviation over mean: 0 for an even floor
};

// Traces the rays: each meets the surface at x, is refracted by Snell's law about the surface's
// normal there (from its slope h'(x)), carries the Fresnel-transmitted share of the sunlight that
// falls on that piece of surface, and goes straight down to the seabed, where its power is added
// to the bin it lands in (its position taken modulo the sea's wavelength: the sea is periodic).
// No absorption: the pattern, not its dimming (multiply by step10::transmittance for that).
// The surface must not shade itself: the sun's zenith angle must stay below the steepest slope's
// complement, atan(1 / (a k)), which holds for any sea gentle enough not to break.
SeabedIrradiance seabed_irradiance(const CausticSea& sea);

// The depth at which a crest focuses sunlight straight from above, to first order: a crest's
// curvature is a k^2, a refracting surface of radius R = 1 / (a k^2) into index n focuses at
// n R / (n - 1) (the thin-lens formula for a single surface).
double crest_focal_depth(const CausticSea& sea);

}  // namespace step10
