// A wave's crest as a lens (README, section 4): the depth at which the crest of a sine wave
// a cos(k x) brings the sun's parallel light, from straight above, to a focus in the water (thin
// lens, the crest's curvature at its top). caustics_reference.hpp's ray tracing finds the
// brightest depth there (tests/test_optics.cpp); exercise 2 derives it.
#pragma once

namespace step10 {

// `amplitude` a (m) and `wavenumber` k (rad/m): metres below the crest.
double crest_focal_depth(double amplitude, double wavenumber);

// The same crest under a sun `sun_zenith` radians from the vertical, shining along the wave (in
// the plane of k, the cylinder's bending plane): the refracted light comes to a line slanted down
// the sun's way, metres below the crest. Exercise 3, a variant no lesson page shows.
double slanted_crest_focal_depth(double amplitude, double wavenumber, double sun_zenith);

}  // namespace step10
