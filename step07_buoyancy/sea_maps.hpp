// Where the queries' maps come from: the same maps the renderer draws, taken three ways.
//   - the double-precision reference (step05's simulate_cpu): the tests' seas;
//   - the FFTW backend's finished maps, already on the CPU (CpuSimulation::levels()), this frame;
//   - the GPU's textures, read back without a stall (map_readback.hpp), one frame late.
#pragma once

#include "step05_fft/cpu_simulation.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step07_buoyancy/sea_surface.hpp"

#include <vector>

namespace step07 {

// The wavenumber by which each of step06's cascades (cascade_spectra(shared)) lets its orbits
// shrink with depth, e^(-k depth): one number for a band of waves, so the one whose waves reach
// deepest, the band's longest energetic waves. That is the spectrum's peak for the band that holds
// it (below the peak the spectrum dies off as exp(-5/4 (omega_p / omega)^4)), and the band's lower
// edge for a band above it (the spectrum falls with k there); a swell's peak counts as the wind
// sea's. Shorter waves of the band shrink faster than it says: the water's motion at depth is
// overestimated a little down to 25 m. Deeper, where the water moves at about 1 % of the surface's
// speed, it can come out a little low (about a fifth at 50 m); tests/test_sea_query.cpp measures
// how much.
std::vector<double> band_wavenumbers(const step05::SpectrumParams& shared);
// The wavenumber of angular frequency omega at depth h: omega^2 = g k tanh(k h) solved for k.
double wavenumber_of(double omega, double depth);

// One cascade's reference maps with choppiness l, in the renderer's layout.
CascadeMaps cascade_maps(const step05::OceanMaps& maps, double choppiness);
// The reference sea of `cascades` at `time` (each simulated in double, then summed); each cascade's
// orbits shrink with depth by wavenumbers[c] (band_wavenumbers; none given: not at all).
MapSea reference_sea(const std::vector<step05::InitialSpectrum>& cascades, double time, double choppiness,
                     const std::vector<double>& wavenumbers = {});
// Level 0 of maps laid out layer major, RGBA, as CpuSimulation and glGetTextureImage give them.
MapSea sea_from_layers(const std::vector<float>& displacement, const std::vector<float>& slopes, int n,
                       const std::vector<double>& tiles, const std::vector<double>& wavenumbers = {});

}  // namespace step07
