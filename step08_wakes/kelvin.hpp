// Chapter 8.3's angle, on its own so that exercise 2 (./ocean exercise step08_wakes 2) can empty
// it: the program draws the wake's edges (kelvin_lines) at the angle it returns for deep water.
#pragma once

namespace step08 {

// The half-angle (radians) of the wake behind a source moving at constant speed over water whose
// waves carry their energy at `group_to_phase` times their phase speed (r = c_g / c: 1/2 in deep
// water), the same for every wave (a model: in water of finite depth r varies with the wavelength):
// from the boat, the edge of the circles on which the energy of the waves made earlier lies. pi / 2 where no such edge exists.
double kelvin_edge_angle(double group_to_phase);

}  // namespace step08
