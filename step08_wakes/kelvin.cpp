#include "step08_wakes/kelvin.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step08 {

double kelvin_edge_angle(double group_to_phase) {
    // The waves made at O, U t behind the boat, that keep pace with it (c = U cos theta) carry their
    // energy n U t cos theta along theta: a circle of radius n U t / 2 whose centre is
    // U t (1 - n / 2) behind the boat, seen from it within arcsin of the radius over that distance.
    const double n = group_to_phase, sine = (n / 2) / (1 - n / 2);
    return n >= 1 ? ocean::kPi / 2 : std::asin(sine);
}

}  // namespace step08
