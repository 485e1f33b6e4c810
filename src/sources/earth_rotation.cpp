#include "sources/earth_rotation.hpp"

#include <erfa.h>

#include <cmath>

namespace conescan::sources {

double earth_rotation_angle_rad(const instant& t, double ut1_minus_utc_s) noexcept {
  const julian_date ut1 = ut1_julian_date(t, ut1_minus_utc_s);
  return eraEra00(ut1.jd1, ut1.jd2);
}

namespace {

// W^T v: the ITRS to the TIRS, W = eraPom00(x_p, y_p, s') the TIRS-to-ITRS matrix (ERFA's rpom
// operates as v_ITRS = rpom v_TIRS).
vec3<double> tirs_from_itrs(const double rpom[3][3], const vec3<double>& v) noexcept {
  return vec3<double>(rpom[0][0] * v.x + rpom[1][0] * v.y + rpom[2][0] * v.z,
                      rpom[0][1] * v.x + rpom[1][1] * v.y + rpom[2][1] * v.z,
                      rpom[0][2] * v.x + rpom[1][2] * v.y + rpom[2][2] * v.z);
}

}  // namespace

cartesian_state inertial_from_itrf(const cartesian_state& itrf, const instant& t,
                                   const earth_orientation_values& eop) noexcept {
  const julian_date tt = tt_julian_date(t);
  double rpom[3][3];
  eraPom00(eop.xp_rad, eop.yp_rad, eraSp00(tt.jd1, tt.jd2), rpom);
  return inertial_from_itrf(
      cartesian_state{tirs_from_itrs(rpom, itrf.r_m), tirs_from_itrs(rpom, itrf.v_m_s)}, t,
      eop.ut1_minus_utc_s);
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
