// Geodetic latitude and altitude on WGS84 (MODEL §2: ECI treated as ECEF; longitude never matters).
#pragma once

#include <cstddef>

#include "conescan/vector.hpp"

namespace conescan::orbit {

struct geodetic_position {
  double lat_rad;  ///< geodetic latitude, [-pi/2, pi/2]
  double alt_m;    ///< height above the WGS84 ellipsoid
};

/// Geodetic latitude and height of any position: Vermeille's closed form for every point more
/// than ~43 km from the centre and closer than 1e20 m (all of them on an orbit), else
/// GeographicLib::Geocentric::WGS84().Reverse. Agrees with GeographicLib to 1e-15 rad in
/// latitude and 8 eps max(a, |r|) in height; within 2.4e-16 rad and 6.9e-16 max(a, |r|) of a
/// 50-digit evaluation (GeographicLib: 3.6e-16 rad, 5.3e-16 max(a, |r|); 2e5 points from 100 km
/// to 1e9 m; tests/orbit/test_orbit.cpp checks both with a margin). NaN in, NaN out.
geodetic_position geodetic_from_eci(const vec3<double>& r_eci_m) noexcept;

/// How many points geodetic_from_eci(positions, out, count) takes through each step together.
inline constexpr std::size_t geodetic_lanes = 4;

/// The same for `count` points, out[i] for r_eci_m[i]: several at once take less time per point
/// than one by one (the closed form is a long chain of dependent steps). Same results.
void geodetic_from_eci(const vec3<double>* r_eci_m, geodetic_position* out,
                       std::size_t count) noexcept;

/// The same by GeographicLib::Geocentric::WGS84().Reverse for every position: the reference
/// geodetic_from_eci is tested against.
geodetic_position geodetic_from_eci_geographiclib(const vec3<double>& r_eci_m) noexcept;

/// Radius of the WGS84 ellipsoid (not inflated) along the direction of r: ab / sqrt(b^2 cos^2
/// phi_c + a^2 sin^2 phi_c) at geocentric latitude phi_c (MODEL §6, processing radius `local`).
double wgs84_radius_along(const vec3<double>& r_eci_m) noexcept;

}  // namespace conescan::orbit
