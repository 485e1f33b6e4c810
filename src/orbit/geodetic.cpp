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

// The WGS84 quantities of Vermeille's closed form, from GeographicLib's a and f (MODEL §3).
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

void geodetic_from_eci(const vec3<double>* r_eci_m, geodetic_position* out,
                       std::size_t count) noexcept {
  // H. Vermeille, "An analytical method to transform geocentric into geodetic coordinates",
  // J. Geodesy 85 (2011) 105-117, evaluated as GeographicLib's Geocentric::Reverse does (C. F. F.
  // Karney's arrangement without cancellation), restricted to an oblate ellipsoid and to points
  // with r > 0, i.e. outside a region of ~43 km about the centre that holds the evolute: there
  // the cubic has one real root and none of GeographicLib's special cases arise. Everything else
  // (the centre, NaN, beyond 1e20 m) goes to GeographicLib itself. Why not always GeographicLib:
  // its Reverse also computes the longitude and converts both angles to degrees with exact
  // quadrant reduction, 934 instructions against ~440 here, a sixth of a CSV row's time
  // (docs/PERFORMANCE.md). tests/orbit/test_orbit.cpp checks that the two agree from the centre to
  // 1e9 m and on both sides of the hand-over.
  //
  // The points go through each step together, geodetic_lanes at a time: one point is a chain of
  // ~350 cycles of dependent square roots, divisions, a cube root and an arctangent, and several
  // independent chains side by side keep the core busy where one leaves it waiting (7 % of a CSV
  // row, docs/PERFORMANCE.md). The arithmetic of each point is the same either way.
  const vermeille_constants& c = vermeille_wgs84();
  for (std::size_t first = 0; first < count; first += geodetic_lanes) {
    const std::size_t n = std::min(geodetic_lanes, count - first);
    const vec3<double>* position = r_eci_m + first;
    geodetic_position* result = out + first;
    double axis_distance[geodetic_lanes], z[geodetic_lanes], q[geodetic_lanes], r[geodetic_lanes],
        cube[geodetic_lanes], t[geodetic_lanes], k[geodetic_lanes], k2[geodetic_lanes];
    bool closed_form[geodetic_lanes];
    for (std::size_t i = 0; i < n; ++i) {
      const double x = position[i].x, y = position[i].y;
      z[i] = position[i].z;
      const double largest = std::max({std::abs(x), std::abs(y), std::abs(z[i])});
      axis_distance[i] = std::sqrt(x * x + y * y);
      const double p = (axis_distance[i] / c.a_m) * (axis_distance[i] / c.a_m);
      q[i] = c.e2m * (z[i] / c.a_m) * (z[i] / c.a_m);
      r[i] = (p + q[i] - c.e4) / 6;
      closed_form[i] = largest <= closed_form_max_coordinate_m && r[i] > 0;
      // r > 0 and S >= 0: the discriminant S (2 r^3 + S) >= 0 and S + r^3 > 0, so one real root
      // with T > 0, u > 0 and u + v > 0 (no cancellation in any of them). A point left to
      // GeographicLib gets harmless values for the rest of the steps.
      if (!closed_form[i]) r[i] = 1, q[i] = 0;
      const double s = c.e4 * p * q[i] / 4;
      const double r3 = r[i] * r[i] * r[i];
      cube[i] = s + r3 + std::sqrt(s * (2 * r3 + s));
    }
    for (std::size_t i = 0; i < n; ++i) t[i] = std::cbrt(cube[i]);
    for (std::size_t i = 0; i < n; ++i) {
      const double u = r[i] + t[i] + r[i] * r[i] / t[i];
      const double v = std::sqrt(u * u + c.e4 * q[i]);
      const double uv = u + v;
      const double w = std::max(0.0, c.e2 * (uv - q[i]) / (2 * v));
      k[i] = uv / (std::sqrt(uv + w * w) + w);
      k2[i] = k[i] + c.e2;
    }
    for (std::size_t i = 0; i < n; ++i)
      result[i].lat_rad = std::atan2(z[i] / k[i], axis_distance[i] / k2[i]);
    for (std::size_t i = 0; i < n; ++i) {
      const double d = k[i] * axis_distance[i] / k2[i];
      result[i].alt_m = (1 - c.e2m / k[i]) * std::sqrt(d * d + z[i] * z[i]);
    }
    for (std::size_t i = 0; i < n; ++i)
      if (!closed_form[i]) result[i] = geodetic_from_eci_geographiclib(position[i]);
  }
}

geodetic_position geodetic_from_eci(const vec3<double>& r_eci_m) noexcept {
  geodetic_position result;
  geodetic_from_eci(&r_eci_m, &result, 1);
  return result;
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
