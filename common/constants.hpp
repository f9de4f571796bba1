// Numbers every chapter shares: one definition each.
#pragma once

namespace ocean {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kGravity = 9.81;  // m/s^2, standard gravity at sea level (rounded as the notes do)

}  // namespace ocean
