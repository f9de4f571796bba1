#include "step08_wakes/kelvin.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step08 {

double kelvin_edge_angle(double group_to_phase) {
    // The waves made at O, U t behind the boat, that keep pace with it (c = U cos theta) carry their
    // energy r U t cos theta along theta (r = c_g / c): a circle of radius r U t / 2 whose centre is
    // U t (1 - r / 2) behind the boat, seen from it within arcsin of the radius over that distance.
    const double r = group_to_phase, sine = (r / 2) / (1 - r / 2);
    return r >= 1 ? ocean::kPi / 2 : std::asin(sine);
}

}  // namespace step08
