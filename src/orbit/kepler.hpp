// Two-body Kepler orbit with optional J2 secular drift (MODEL §3).
#pragma once

#include <cstddef>

#include "conescan/vector.hpp"

namespace conescan::orbit {

/// Classical elements at t = 0 (SI, rad).
struct elements {
  double a_m;
  double e;
  double i_rad;
  double raan_rad;
  double argp_rad;
  double m0_rad;
};

/// Linear rates of the angles (rad/s): two-body, or two-body plus J2 secular terms.
struct secular_rates {
  double raan_dot;
  double argp_dot;
  double mean_anomaly_dot;
};

/// Position, velocity of the osculating ellipse, and true anomaly at one time.
struct orbit_state {
  vec3<double> r_eci_m;
  vec3<double> v_eci_m_s;
  double true_anomaly_rad;  ///< not wrapped: carries the whole turns of the mean anomaly
};

/// Eccentric anomaly E solving Kepler's equation E - e sin E = M for 0 <= e < 1, any finite M.
/// M is reduced to (-pi, pi] (wrap_pi), where E lies in the bracket [M, M + e sin-sign]: Newton
/// from Danby's start (3 to 6 steps in double; from M / (1 - e) where E is small), the core's
/// bracketed_newton if that has not converged in 16 (never diverges). The whole turns removed
/// from M are added back. Accuracy: 1.3 ulp of E relative (measured for e up to 0.999999 and
/// M from 1e-12 to 3; the residual is written without cancellation where E is small and e >=
/// 1/2), relative down to M = 1e-300 (tests/orbit/test_orbit.cpp, against a long double bisection).
double eccentric_anomaly(double mean_anomaly_rad, double e) noexcept;

/// A solution of Kepler's equation with the sine and cosine of E, which the position needs:
/// the solver has them from its last Newton step. sin_e and cos_e are those of the reduced
/// E - turns_rad in (-pi, pi] (exact in the angle, unlike sin of the unreduced E), to ~1 ulp.
struct kepler_solution {
  double eccentric_anomaly_rad;  ///< as eccentric_anomaly returns it
  double turns_rad;              ///< the whole turns removed from M: M - wrap_pi(M)
  double sin_e, cos_e;
};

/// eccentric_anomaly with sin E and cos E (same accuracy). sin and cos come from libm where
/// Newton's iterate is more than 2^-10 from the last libm evaluation, else from that one by the
/// angle-difference formulas (two sincos per solve at e = 0.1); Newton stops once its step is
/// below 2^-26 of E and its quadratic error estimate below eps / 8 relative to E.
kepler_solution solve_kepler(double mean_anomaly_rad, double e) noexcept;

/// How many solves solve_kepler(mean_anomalies, e, out, count) takes through each step together.
inline constexpr std::size_t kepler_lanes = 4;

/// The same for `count` mean anomalies of one eccentricity, out[i] for mean_anomaly_rad[i]:
/// several at once take less time per solve than one by one. Same results, bit for bit.
void solve_kepler(const double* mean_anomaly_rad, double e, kepler_solution* out,
                  std::size_t count) noexcept;

/// nu from a Kepler solution without further sines: tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2), in
/// the half-plane of E, with the whole turns of E. Agrees with true_anomaly_from_eccentric to
/// rounding (tests/orbit/test_orbit.cpp).
double true_anomaly_from_kepler(const kepler_solution& k, double e) noexcept;

/// nu from E: 2 atan2(sqrt(1+e) sin(E/2), sqrt(1-e) cos(E/2)), continuous in E.
double true_anomaly_from_eccentric(double eccentric_anomaly_rad, double e) noexcept;

/// E from nu, the inverse: 2 atan2(sqrt(1-e) sin(nu/2), sqrt(1+e) cos(nu/2)).
double eccentric_from_true_anomaly(double true_anomaly_rad, double e) noexcept;

/// Two-body period 2 pi sqrt(a^3 / GM), s ("one orbit" of MODEL §3, also with J2).
double orbital_period_s(double a_m, double gm_m3_s2) noexcept;

/// Two-body rates: the mean motion n = sqrt(GM / a^3), Omega and omega fixed.
secular_rates two_body_rates(const elements& el, double gm_m3_s2) noexcept;

/// MODEL §3's J2 secular rates, p = a(1-e^2), R = equatorial radius:
///   Omega' = -(3/2) n J2 (R/p)^2 cos i;  omega' = (3/4) n J2 (R/p)^2 (5 cos^2 i - 1);
///   M' = n + (3/4) n J2 (R/p)^2 sqrt(1-e^2) (3 cos^2 i - 1).
secular_rates j2_secular_rates(const elements& el, double gm_m3_s2, double j2,
                               double r_eq_m) noexcept;

/// Days per tropical year and the node rate of a sun-synchronous orbit (MODEL §3).
inline constexpr double tropical_year_days = 365.2421897;

/// cos i of the sun-synchronous orbit with the given a, e: -Omega'_ss / ((3/2) n J2 (R/p)^2).
/// Outside [-1, 1] no such orbit exists (the caller reports it).
double sun_synchronous_cos_inclination(double a_m, double e, double gm_m3_s2, double j2,
                                       double r_eq_m) noexcept;

/// State at time t (s): Omega, omega and M advance linearly by `rates`; a, e, i stay; r and v
/// follow from the elements at t by the two-body formulas (MODEL §3).
orbit_state state_at(const elements& el, const secular_rates& rates, double gm_m3_s2,
                     double t_s) noexcept;

/// The same for many times of one orbit: without node or perigee drift (two-body) the
/// perifocal axes are computed once, so a state costs one Kepler solve and a few products.
/// Results equal state_at's bit for bit.
class kepler_orbit {
 public:
  kepler_orbit() = default;
  kepler_orbit(const elements& el, const secular_rates& rates, double gm_m3_s2) noexcept;
  orbit_state state_at(double t_s) const noexcept;
  /// out[i] = state_at(t_s[i]) for i < count, bit for bit, in less time per state on a
  /// two-body orbit (the Kepler solves run kepler_lanes at a time).
  void states_at(const double* t_s, orbit_state* out, std::size_t count) const noexcept;

 private:
  elements elements_{};
  secular_rates rates_{};
  double gm_ = 0;
  vec3<double> p_axis_{0.0}, q_axis_{0.0};  // perifocal axes at t = 0, ECI
};

}  // namespace conescan::orbit
