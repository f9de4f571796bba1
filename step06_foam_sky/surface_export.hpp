// step06's --export: the rendered sea, not one cascade. The sum of the four cascades (as
// foam.frag sees it) and the foam, on the texel centres of one foam level's window around the
// camera: height.pfm, jacobian.pfm and foam.pfm lie on the same grid, so a test from outside can
// ask whether the foam sits on the crests and where the crests go.
#pragma once

#include "common/params.hpp"
#include "common/shader.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/short_waves.hpp"

#include <string>

namespace step06 {

constexpr int kExportedFoamLevel = 1;  // 256 m around the camera: several peak wavelengths

// The maps hold the simulated surface; export.txt also gives the slope variance of the waves
// shorter than the last cascade (`short_waves`, export.short_wave_slope_variance_upwind and
// _crosswind), which the renderer adds as roughness.
void export_surface(const std::string& dir, ocean::ProgramFactory& programs, const step05::OceanSimulation& ocean,
                    const FoamSimulation& foam, const CascadeView& cascades, double time, double choppiness,
                    const SlopeVariance& short_waves, const ocean::ParamRegistry& params);

}  // namespace step06
