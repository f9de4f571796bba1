// The chapter's experiments, run on the CPU in double precision: what the tests hold to the
// physics and what the README's figures plot (./ocean figures), so the numbers quoted are the code's.
#pragma once

#include "step08_wakes/wave_field.hpp"

#include <vector>

namespace step08 {

// A deep-water field of n cells of `cell` metres, an absorbing layer `layer` of its side wide at
// each edge, damping at `rate` per second at the very edge.
WaveFieldSettings deep_field(int n, double cell, double layer, double rate);

// A pressure patch (a Gaussian of standard deviation length / 4: 86 % of it within a circle
// `length` across) towed along +x at `speed` over deep water for `seconds`, on a grid following
// it by whole cells (the patch a quarter of the grid ahead of its centre, so the wake fills the
// rest).
struct TowedPatch {
    double speed = 2;          // m/s
    double length = 0.85;      // m
    double pressure = 50;      // p / rho at the centre, m^2/s^2 (50: 5 kPa, a light hull's)
    double seconds = 14;
    int n = 256;
    double cell = 0.1;         // m
};
// The field when the tow ends, and where the patch is (x, z).
struct TowedWake {
    WaveField field;
    glm::dvec2 patch;
};
TowedWake tow(const TowedPatch& tow);

// Kelvin's wavelength 2 pi U^2 / g: the transverse waves', which keep pace with the source.
double transverse_wavelength(double speed);
// The Froude number U / sqrt(g L) of a source of length L.
double froude_number(double speed, double length);

// The angle (degrees) from the track of the wake's largest waves: at each distance behind the
// patch from `from` to `to` metres (every cell), the lateral distance y at which the wave envelope
// (the largest |eta| within half a transverse wavelength along the track) peaks, both sides
// averaged; the angle is the median of atan(y / x) over the distances (Rabaud and Moisy's measure).
double largest_wave_angle(const TowedWake& wake, double speed, double from, double to);
// The angle (degrees) of the wake's edge, Kelvin's caustic: at each distance, the outermost y at
// which the envelope is still half its largest (past the caustic the waves die away within a few
// of their own lengths); the median over the distances.
double wake_edge_angle(const TowedWake& wake, double speed, double from, double to);

// Cauchy-Poisson: the crests along a ray from an impulse at the grid's centre, `t` seconds after
// it, between radii `from` and `to`: their radii, nearest first (the radially averaged field's
// local maxima).
std::vector<double> ring_crests(const WaveField& field, double from, double to);

}  // namespace step08
