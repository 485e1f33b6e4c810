// Geodetic latitude and altitude on WGS84 (SPEC §2: ECI treated as ECEF; longitude never matters).
#pragma once

#include "conescan/vector.hpp"

namespace conescan::orbit {

struct geodetic_position {
  double lat_rad;  ///< geodetic latitude, [-pi/2, pi/2]
  double alt_m;    ///< height above the WGS84 ellipsoid
};

/// GeographicLib::Geocentric::WGS84().Reverse: exact to a few nm for any position (its docs).
geodetic_position geodetic_from_eci(const vec3<double>& r_eci_m) noexcept;

/// Radius of the WGS84 ellipsoid (not inflated) along the direction of r: ab / sqrt(b^2 cos^2
/// phi_c + a^2 sin^2 phi_c) at geocentric latitude phi_c (SPEC §6, processing radius `local`).
double wgs84_radius_along(const vec3<double>& r_eci_m) noexcept;

}  // namespace conescan::orbit
