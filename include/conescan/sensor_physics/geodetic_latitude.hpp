// The WGS84 geodetic latitude of a point given by its distance from the polar axis and its height
// along it (MODEL §12: the season term's latitude is the WGS84 geodetic latitude of the tangent
// point on every Earth model, the sphere included). The core may not use GeographicLib, so
// WGS84's two defining numbers are written here (tests/core/test_sensor_physics_heights.cpp checks
// them, and the latitude against the forward closed form from latitude and height).
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
/// contracts by about e^2 = 0.0067 per step. It starts from Bowring's formula (his parametric
/// latitude u, tan u = a z / (b rho), then tan phi = (z + e'^2 b sin^3 u) / (rho - e^2 a cos^3 u)),
/// close to the latitude near the surface where the geocentric start is 3e-3 off, and stops when
/// a step moves the sine by less than a quarter ulp (at most 16 steps). In double, every 0.1 deg
/// of latitude: 1.3 steps on average on the surface, 2.8 at 40 km up (at most 4), 3.7 at
/// 1000 km (at most 5), where the geocentric start took 6.5 (at most 8); half the time a call.
/// Measured against the forward closed form, every 2.5 deg of latitude from the surface to 10^6
/// km up: within 8.2e-8 in float, 1.5e-16 in double, 1.1e-19 in long double
/// (tests/core/test_sensor_physics_heights.cpp). Domain: rho, z finite; the centre (both 0)
/// returns 0.
template <class T>
T wgs84_sin_geodetic_latitude(const T& rho_m, const T& z_m) noexcept {
  using std::sqrt;
  const T a = wgs84_equatorial_radius_m<T>(), f = wgs84_flattening<T>();
  const T e2 = f * (T(2) - f);
  const T b = a * (T(1) - f);
  const T az = a * z_m, b_rho = b * rho_m;
  const T hypotenuse = sqrt(az * az + b_rho * b_rho);
  if (!(hypotenuse > T(0))) return T(0);
  const T sin_u = az / hypotenuse, cos_u = b_rho / hypotenuse;
  const T along = z_m + e2 / (T(1) - e2) * b * sin_u * sin_u * sin_u;
  const T across = rho_m - e2 * a * cos_u * cos_u * cos_u;
  T sin_phi = along / sqrt(along * along + across * across);
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
