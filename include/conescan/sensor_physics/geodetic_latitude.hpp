// The WGS84 geodetic latitude of a point given by its distance from the polar axis and its height
// along it (MODEL §12: the season term's latitude is the WGS84 geodetic latitude of the tangent
// point on every Earth model, the sphere included). The core may not use GeographicLib, so
// WGS84's two defining numbers are written here (tests/core/test_sensor_physics_heights.cpp checks
// them and the latitude against GeographicLib's Geocentric::Reverse).
#pragma once

#include <cmath>
#include <limits>

namespace conescan {

/// WGS84's equatorial radius (m) and flattening, as GeographicLib's Constants give them.
template <class T>
T wgs84_equatorial_radius_m() noexcept {
  return T(6378137);
}
template <class T>
T wgs84_flattening() noexcept {
  return T(1) / (T(298257223563LL) / T(1000000000));
}

/// sin of the WGS84 geodetic latitude of the point at distance rho_m >= 0 from the polar axis
/// and z_m along it (from the Earth's centre). The fixed-point iteration
///   sin phi <- t / sqrt(rho^2 + t^2),  t = z + e^2 N(phi) sin phi,  N = a / sqrt(1 - e^2 sin^2
///   phi),
/// started at the geocentric latitude, contracts by about e^2 = 0.0067 per step: it stops when a
/// step moves the sine by less than a quarter ulp (7 steps in double, 9 in long double, at most
/// 16), for any point at or above the surface (tested against
/// GeographicLib at heights 0 to 10^6 km, every latitude). Domain: rho, z finite, not both 0 (the
/// centre: 0 is returned).
template <class T>
T wgs84_sin_geodetic_latitude(const T& rho_m, const T& z_m) noexcept {
  using std::sqrt;
  const T a = wgs84_equatorial_radius_m<T>(), f = wgs84_flattening<T>();
  const T e2 = f * (T(2) - f);
  const T r = sqrt(rho_m * rho_m + z_m * z_m);
  if (!(r > T(0))) return T(0);
  T sin_phi = z_m / r;
  const T eps = std::numeric_limits<T>::epsilon();
  for (int step = 0; step < 16; ++step) {
    const T n = a / sqrt(T(1) - e2 * sin_phi * sin_phi);
    const T t = z_m + e2 * n * sin_phi;
    const T next = t / sqrt(rho_m * rho_m + t * t);
    const T change = next - sin_phi;
    sin_phi = next;
    if (!(change > eps / T(4) || -change > eps / T(4))) break;
  }
  return sin_phi;
}

}  // namespace conescan
