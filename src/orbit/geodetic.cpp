#include "orbit/geodetic.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <cmath>

#include "conescan/scalar.hpp"
#include "orbit/wgs84.hpp"

namespace conescan::orbit {

geodetic_position geodetic_from_eci(const vec3<double>& r_eci_m) noexcept {
  double lat_deg = 0, lon_deg = 0, h_m = 0;
  GeographicLib::Geocentric::WGS84().Reverse(r_eci_m.x, r_eci_m.y, r_eci_m.z, lat_deg, lon_deg,
                                             h_m);
  return {deg_to_rad(lat_deg), h_m};
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
