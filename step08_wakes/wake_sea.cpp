#include "step08_wakes/wake_sea.hpp"

namespace step08 {

step07::SurfaceAt SeaWithWake::at(glm::dvec2 rest) const {
    step07::SurfaceAt s = sea_.at(rest);
    const step06::ExtraWaveSample w = step06::extra_waves_at(wake_, rest);
    s.displacement += glm::dvec3(w.displacement);
    // d/dx of (l Dx, h, l Dz) is (l dDx/dx, dh/dx, l dDz/dx), and dDz/dx = dDx/dz (a gradient's
    // mixed derivatives); d/dz is (l dDx/dz, dh/dz, l dDz/dz).
    s.d_dx += glm::dvec3(w.slopes.z, w.slopes.x, w.displacement.w);
    s.d_dz += glm::dvec3(w.displacement.w, w.slopes.y, w.slopes.w);
    return s;
}

glm::dvec3 SeaWithWake::displacement_below(glm::dvec2 rest, double depth) const {
    return sea_.displacement_below(rest, depth) +
           glm::dvec3(step06::extra_waves_at(wake_, rest).displacement);
}

}  // namespace step08
