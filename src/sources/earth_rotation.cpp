#include "sources/earth_rotation.hpp"

#include <erfa.h>

#include <cmath>

namespace conescan::sources {

double earth_rotation_angle_rad(const instant& t, double ut1_minus_utc_s) noexcept {
  const julian_date ut1 = ut1_julian_date(t, ut1_minus_utc_s);
  return eraEra00(ut1.jd1, ut1.jd2);
}

cartesian_state inertial_from_itrf(const cartesian_state& itrf, const instant& t,
                                   double ut1_minus_utc_s) noexcept {
  const double era = earth_rotation_angle_rad(t, ut1_minus_utc_s);
  const double c = std::cos(era), s = std::sin(era);
  // R3(-ERA): the Earth-fixed x axis points at angle ERA from the CIO.
  const auto turn = [c, s](const vec3<double>& a) {
    return vec3<double>(c * a.x - s * a.y, s * a.x + c * a.y, a.z);
  };
  const vec3<double> omega_cross_r(-earth_rotation_rate_rad_s * itrf.r_m.y,
                                   earth_rotation_rate_rad_s * itrf.r_m.x, 0.0);
  return cartesian_state{turn(itrf.r_m), turn(itrf.v_m_s + omega_cross_r)};
}

}  // namespace conescan::sources
