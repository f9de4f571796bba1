// Chapter 8.6: the sea the bodies float on, with the wake in it. step07's bodies ask a Surface for
// the displacement of the point resting at x and its derivatives; here the answer is the sea's
// (step07's MapSea) plus the wake's maps (wake_maps.hpp), read as step06's extra_waves.glsl reads
// them (step06::extra_waves_at): bilinear between cell centres, nothing outside the grid. So a buoy
// rides the wake the window shows.
#pragma once

#include "step06_foam_sky/extra_waves.hpp"
#include "step07_buoyancy/sea_surface.hpp"

namespace step08 {

class SeaWithWake : public step07::Surface {
public:
    // Both are read, not copied: they must outlive this.
    SeaWithWake(const step07::Surface& sea, const step06::ExtraWaveMaps& wake) : sea_(sea), wake_(wake) {}
    step07::SurfaceAt at(glm::dvec2 rest) const override;
    // The sea's water below the surface, plus the wake's surface motion, not shrunk with depth:
    // the wake's waves are a few metres long and a hull's cells a metre deep at most, so this
    // overstates the wake's push on the deepest cells a little (e^(-k depth) >= 0.5 for waves
    // longer than 9 m at 1 m down), never hides it.
    glm::dvec3 displacement_below(glm::dvec2 rest, double depth) const override;

private:
    const step07::Surface& sea_;
    const step06::ExtraWaveMaps& wake_;
};

}  // namespace step08
