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

// One cascade's reference maps with choppiness l, in the renderer's layout.
CascadeMaps cascade_maps(const step05::OceanMaps& maps, double choppiness);
// The reference sea of `cascades` at `time` (each simulated in double, then summed).
MapSea reference_sea(const std::vector<step05::InitialSpectrum>& cascades, double time, double choppiness);
// Level 0 of maps laid out layer major, RGBA, as CpuSimulation and glGetTextureImage give them.
MapSea sea_from_layers(const std::vector<float>& displacement, const std::vector<float>& slopes, int n,
                       const std::vector<double>& tiles);

}  // namespace step07
