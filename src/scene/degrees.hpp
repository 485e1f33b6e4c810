// Degrees as users type them, to radians for the simulation.
#pragma once

#include <cmath>

#include "conescan/scalar.hpp"

namespace conescan::scene {

/// An angle in degrees to radians in (-pi, pi], reduced in degrees first: std::remainder by 360
/// is exact, so --roll-deg 1e20 is the angle 1e20 mod 360 = -80 deg. Converting first would
/// multiply the rounding of 1e20 pi / 180 (ulp 1.6e4 rad) into the angle: a roll of 1e20 deg
/// came out 100 deg off with status ok.
inline double deg_to_rad_reduced(double deg) {
  return deg_to_rad(std::remainder(deg, 360.0));
}

}  // namespace conescan::scene
