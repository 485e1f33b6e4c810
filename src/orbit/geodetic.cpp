#include "orbit/geodetic.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <algorithm>
#include <cmath>

#include "conescan/scalar.hpp"
#include "orbit/wgs84.hpp"

namespace conescan::orbit {

geodetic_position geodetic_from_eci_geographiclib(const vec3<double>& r_eci_m) noexcept {
  double lat_deg = 0, lon_deg = 0, h_m = 0;
  GeographicLib::Geocentric::WGS84().Reverse(r_eci_m.x, r_eci_m.y, r_eci_m.z, lat_deg, lon_deg,
                                             h_m);
  return {deg_to_rad(lat_deg), h_m};
}

namespace {

// The WGS84 quantities of Vermeille's closed form, from GeographicLib's a and f (SPEC §3).
struct vermeille_constants {
  double a_m, e2, e2m, e4;  // a; e^2 = f (2 - f); 1 - e^2 = (1 - f)^2; e^4
};

const vermeille_constants& vermeille_wgs84() noexcept {
  static const vermeille_constants c = [] {
    const earth_constants& w = wgs84();
    const double e2 = w.f * (2 - w.f);
    return vermeille_constants{w.a_m, e2, (1 - w.f) * (1 - w.f), e2 * e2};
  }();
  return c;
}

// Largest coordinate the closed form below takes: its squares stay far from overflow, and the
// point stays far inside GeographicLib's own "treat the Earth as a point" radius (2 a / eps).
constexpr double closed_form_max_coordinate_m = 1e20;

}  // namespace

geodetic_position geodetic_from_eci(const vec3<double>& r_eci_m) noexcept {
  // H. Vermeille, "An analytical method to transform geocentric into geodetic coordinates",
  // J. Geodesy 85 (2011) 105-117, evaluated as GeographicLib's Geocentric::Reverse does (C. F. F.
  // Karney's arrangement without cancellation), restricted to an oblate ellipsoid and to points
  // with r > 0, i.e. outside a region of ~43 km about the centre that holds the evolute: there
  // the cubic has one real root and none of GeographicLib's special cases arise. Everything else
  // (the centre, NaN, beyond 1e20 m) goes to GeographicLib itself. Why not always GeographicLib:
  // its Reverse also computes the longitude and converts both angles to degrees with exact
  // quadrant reduction, 934 instructions against ~330 here, a fifth of a CSV row
  // (docs/PERFORMANCE.md). tests/test_orbit.cpp checks that the two agree from the centre to
  // 1e9 m and on both sides of the hand-over.
  const vermeille_constants& c = vermeille_wgs84();
  const double x = r_eci_m.x, y = r_eci_m.y, z = r_eci_m.z;
  const double largest = std::max({std::abs(x), std::abs(y), std::abs(z)});
  const double axis_distance = std::sqrt(x * x + y * y);
  const double p = (axis_distance / c.a_m) * (axis_distance / c.a_m);
  const double q = c.e2m * (z / c.a_m) * (z / c.a_m);
  const double r = (p + q - c.e4) / 6;
  if (!(largest <= closed_form_max_coordinate_m) || !(r > 0))
    return geodetic_from_eci_geographiclib(r_eci_m);
  // r > 0 and S >= 0: the discriminant S (2 r^3 + S) >= 0 and S + r^3 > 0, so one real root
  // with T > 0, u > 0 and u + v > 0 (no cancellation in any of them).
  const double s = c.e4 * p * q / 4;
  const double r2 = r * r, r3 = r * r2;
  const double t = std::cbrt(s + r3 + std::sqrt(s * (2 * r3 + s)));
  const double u = r + t + r2 / t;
  const double v = std::sqrt(u * u + c.e4 * q);
  const double uv = u + v;
  const double w = std::max(0.0, c.e2 * (uv - q) / (2 * v));
  const double k = uv / (std::sqrt(uv + w * w) + w);
  const double k2 = k + c.e2;
  const double d = k * axis_distance / k2;
  return {std::atan2(z / k, axis_distance / k2), (1 - c.e2m / k) * std::sqrt(d * d + z * z)};
}

double wgs84_radius_along(const vec3<double>& r_eci_m) noexcept {
  const earth_constants& e = wgs84();
  // cos and sin of the geocentric latitude, without forming the angle.
  const double rho = std::hypot(r_eci_m.x, r_eci_m.y);
  const double r = std::hypot(rho, r_eci_m.z);
  const double cos_lat = rho / r, sin_lat = r_eci_m.z / r;
  return e.a_m * e.b_m / std::hypot(e.b_m * cos_lat, e.a_m * sin_lat);
}

}  // namespace conescan::orbit
