// WGS84 constants, all from GeographicLib (MODEL §3).
#pragma once

namespace conescan::orbit {

struct earth_constants {
  double a_m;       ///< equatorial radius, m
  double f;         ///< flattening
  double b_m;       ///< polar radius a (1 - f), m
  double gm_m3_s2;  ///< gravitational parameter, m^3/s^2
  double j2;        ///< dynamical form factor J2 (NormalGravity::WGS84().DynamicalFormFactor(2))
};

/// The WGS84 values: Constants::WGS84_a(), WGS84_f(), WGS84_GM() and NormalGravity::WGS84().
const earth_constants& wgs84() noexcept;

}  // namespace conescan::orbit
