// step06's --export: the rendered sea, not one cascade. The sum of the four cascades (as
// foam.comp sees it) and the foam, on the texel centres of one foam level's window around the
// camera: height.pfm, jacobian.pfm and foam.pfm lie on the same grid, so a test from outside can
// ask whether the foam sits on the crests and where the crests go.
#pragma once

#include "common/params.hpp"
#include "common/shader.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/foam.hpp"

#include <string>

namespace step06 {

constexpr int kExportedFoamLevel = 1;  // 256 m around the camera: several peak wavelengths

void export_surface(const std::string& dir, ocean::ProgramFactory& programs, const step05::OceanSimulation& ocean,
                    const FoamSimulation& foam, const CascadeView& cascades, double time, double choppiness,
                    const ocean::ParamRegistry& params);

}  // namespace step06
