#include "orbit/kepler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "conescan/root_finding.hpp"

namespace conescan::orbit {

namespace {

// sin and cos at E = anchor - d from the anchor's (|d| <= 2^-10): the angle-difference formulas
// with Taylor series for d, terms to d^5 and d^4 (the next are below 2^-60). Products by rounded
// reciprocals, not divisions (~13 cycles each on the solve's chain): they change the correction
// terms, at most 2^-30 of sin d, by an ulp of their own.
void near_anchor(double sin_anchor, double cos_anchor, double d, double& sin_out,
                 double& cos_out) noexcept {
  const double d2 = d * d;
  constexpr double sixth = 1.0 / 6, twentieth = 1.0 / 20, twelfth = 1.0 / 12;
  const double sin_d = d - d * d2 * sixth * (1 - d2 * twentieth);
  const double one_minus_cos_d = d2 * 0.5 * (1 - d2 * twelfth);
  sin_out = sin_anchor - (sin_anchor * one_minus_cos_d + cos_anchor * sin_d);
  cos_out = cos_anchor - (cos_anchor * one_minus_cos_d - sin_anchor * sin_d);
}

// E - sin E and 1 - cos E for 0 <= E <= small_e_series_max by their Taylor series, terms to E^21
// and E^20 (the next are below 2^-68 of the first at E = 1): without the cancellation of
// E - sin E. Coefficients 1 / k!, rounded.
constexpr double small_e_series_max = 1;
void small_angle_complements(double x, double& x_minus_sin, double& one_minus_cos) noexcept {
  constexpr double odd[] = {1.0 / 6,
                            1.0 / 120,
                            1.0 / 5040,
                            1.0 / 362880,
                            1.0 / 39916800,
                            1.0 / 6227020800,
                            1.0 / 1307674368000,
                            1.0 / 355687428096000,
                            1.0 / 121645100408832000,
                            1.0 / 51090942171709440000.0};
  constexpr double even[] = {1.0 / 2,
                             1.0 / 24,
                             1.0 / 720,
                             1.0 / 40320,
                             1.0 / 3628800,
                             1.0 / 479001600,
                             1.0 / 87178291200,
                             1.0 / 20922789888000,
                             1.0 / 6402373705728000,
                             1.0 / 2432902008176640000.0};
  const double x2 = x * x;
  double s = odd[9], c = even[9];
  for (int k = 8; k >= 0; --k) {  // Horner in x^2, alternating signs
    s = odd[k] - x2 * s;
    c = even[k] - x2 * c;
  }
  x_minus_sin = x * x2 * s;
  one_minus_cos = x2 * c;
}

// Kepler's residual E - e sin E - |M| and its slope 1 - e cos E at E >= 0. Where e >= 1/2 and E is
// small both cancel (E ~ e sin E, 1 ~ e cos E): there they are (1 - e) E + e (E - sin E) - |M|
// and (1 - e) + e (1 - cos E), with 1 - e exact (Sterbenz) and the complements by their series,
// so that E keeps its relative accuracy as M -> 0 for e -> 1 (the plain form lost 1e6 ulp at
// e = 0.999999, M = 1.5e-10; 22 ulp at e = 0.999, E = 0.29). Below e = 1/2 the plain form loses
// less than an ulp; beyond E = 1 the cancellation is at most a factor 6.
value_slope<double> kepler_residual(double ecc, double sin_e, double cos_e, double e,
                                    double abs_m) noexcept {
  if (e >= 0.5 && ecc <= small_e_series_max) {
    double ecc_minus_sin, one_minus_cos;
    small_angle_complements(ecc, ecc_minus_sin, one_minus_cos);
    return {(1 - e) * ecc + e * ecc_minus_sin - abs_m, (1 - e) + e * one_minus_cos};
  }
  return {ecc - e * sin_e - abs_m, 1 - e * cos_e};
}

// The state of one solve between Newton steps.
struct kepler_lane {
  double turns, sign, abs_m;
  double newton;                  // the iterate E (of |M|)
  double anchor;                  // where sin and cos last came from libm
  double sin_anchor, cos_anchor;  // theirs
  double sin_e, cos_e;            // at the iterate
  bool active;                    // not yet returned
  bool refresh;                   // the iterate left the anchor's 2^-10: call libm again
  bool last;                      // this step is the last

  // Moves the anchor to the iterate: sin and cos from libm there.
  void anchor_at_iterate() noexcept {
    anchor = newton;
    sin_e = sin_anchor = std::sin(anchor);
    cos_e = cos_anchor = std::cos(anchor);
  }
};

// Where Newton starts from the series' first term M / (1 - e) (below 2^-10 (1 - e)), and how far
// from the anchor sin and cos come from near_anchor (2^-10).
constexpr double small_e_bound = 0x1p-10, series_max = 0x1p-10;

// A lane's start for the mean anomaly `mean_anomaly` (any turn): false, with `out` written, where
// E = M exactly (M a whole number of turns, or a circle).
bool start_lane(kepler_lane& l, double mean_anomaly, double e, kepler_solution& out) noexcept {
  const double m = wrap_pi(mean_anomaly);  // (-pi, pi], by remainder
  l.turns = mean_anomaly - m;
  l.active = !(m == 0 || e == 0);
  if (!l.active) {
    out = {mean_anomaly, l.turns, std::sin(m), std::cos(m)};
    return false;
  }
  // E - M = e sin E has the sign of M on [-pi, pi], and |E - M| <= e.
  l.sign = m > 0 ? 1.0 : -1.0;
  l.abs_m = std::abs(m);
  l.newton = l.abs_m < small_e_bound * (1 - e) ? l.abs_m / (1 - e) : l.abs_m + 0.85 * e;
  return true;
}

// One Newton step of an active lane: the new iterate, whether it is the last, and sin and cos
// there from the anchor's where it is near (l.refresh where libm must be called).
void newton_step(kepler_lane& l, double e) noexcept {
  const value_slope<double> f = kepler_residual(l.newton, l.sin_e, l.cos_e, e, l.abs_m);
  const double slope = f.slope;
  const double step = f.value / slope;
  l.newton -= step;
  const double d = l.anchor - l.newton;
  // This step is the last once both hold, relative to E (which can be tiny: E ~ M / (1 - e)):
  //  - |step| <= 2^-26 E: the step was computed from a residual at E + step, so its rounding is
  //    ~eps (E + step), an ulp of E;
  //  - Newton's error after the step, (e sin E / (2 slope)) step^2 to leading order (quadratic
  //    convergence), <= (e / (2 slope)) step^2, is at most eps / 8 relative to E.
  // An absolute test here once returned E for M = 1e-12 to 300 ulp only
  // (tests/orbit/test_orbit.cpp, small M).
  l.last = std::abs(step) <= 0x1p-26 * l.newton &&
           e * step * step <= slope * (std::numeric_limits<double>::epsilon() / 4) * l.newton;
  l.refresh = !(std::abs(d) <= series_max);
  if (!l.refresh) near_anchor(l.sin_anchor, l.cos_anchor, d, l.sin_e, l.cos_e);
}

// Up to 16 Newton steps of n lanes side by side; each lane that converges writes its solution to
// out[i] and leaves the active ones.
void newton_lanes(kepler_lane* lane, std::size_t n, double e, kepler_solution* out) noexcept {
  for (std::size_t i = 0; i < n; ++i)
    if (lane[i].active) lane[i].anchor_at_iterate();
  for (int step_count = 0; step_count < 16; ++step_count) {
    bool any_active = false;
    for (std::size_t i = 0; i < n; ++i)
      if (lane[i].active) newton_step(lane[i], e);
    for (std::size_t i = 0; i < n; ++i)
      if (lane[i].active && lane[i].refresh) lane[i].anchor_at_iterate();
    for (std::size_t i = 0; i < n; ++i) {
      kepler_lane& l = lane[i];
      if (!l.active) continue;
      if (l.last) {
        out[i] = {l.turns + l.sign * l.newton, l.turns, l.sign * l.sin_e, l.cos_e};
        l.active = false;
      }
      any_active = any_active || l.active;
    }
    if (!any_active) break;
  }
}

// The bracketed solver, for a lane Newton did not finish.
kepler_solution bracketed_solve(const kepler_lane& l, double e) noexcept {
  const double abs_m = l.abs_m;
  const double hi = std::min(abs_m + e, pi<double>());
  auto kepler = [&](double ecc) {
    return kepler_residual(ecc, std::sin(ecc), std::cos(ecc), e, abs_m);
  };
  // Starting guess: M + e sin M is good for small e; pi for the high-e, small-M corner.
  const double guess = e < 0.8 ? abs_m + e * std::sin(abs_m) : pi<double>();
  const double ecc = bracketed_newton(kepler, abs_m, hi, guess).x;
  return {l.turns + l.sign * ecc, l.turns, l.sign * std::sin(ecc), std::cos(ecc)};
}

}  // namespace

void solve_kepler(const double* mean_anomaly_rad, double e, kepler_solution* out,
                  std::size_t count) noexcept {
  // Plain Newton from Danby's start E0 = M + 0.85 e (Danby 1987, for M in [0, pi]), which
  // converges for every e < 1, in 3 to 6 steps in double; the bracketed solver only backs it up
  // (it costs an extra evaluation per call, a tenth of a CLI row). Where E is small,
  // E = M / (1 - e) - e M^3 / (6 (1 - e)^4) + ...: from Danby's start Newton would come down
  // from ~e by a factor of only ~1e-14 per step once rounding dominates (M = 1e-300 was not
  // reached in 16 steps), so it starts from the series' first term, off by a relative
  // e E^2 / (6 (1 - e)) at most, and converges in 1 to 3 steps.
  //
  // sin and cos of E come from std::sin and std::cos at an anchor, and near it (within 2^-10)
  // from the anchor's (near_anchor): the step after a libm evaluation is often already that
  // small (e = 0.1: 0.1, then 5e-4, then 1e-8), which saves a sincos per solve
  // (docs/PERFORMANCE.md). Each value is one update from libm's, so it keeps their accuracy;
  // d = anchor - E is exact (Sterbenz) or below an ulp of 2^-62.
  //
  // The solves go through each step together, kepler_lanes at a time: one solve is a chain of
  // dependent sines, divisions and tests, and independent chains side by side keep the core
  // busy. Each solve's arithmetic is the same either way.
  for (std::size_t first = 0; first < count; first += kepler_lanes) {
    const std::size_t n = std::min(kepler_lanes, count - first);
    kepler_lane lane[kepler_lanes];
    for (std::size_t i = 0; i < n; ++i)
      start_lane(lane[i], mean_anomaly_rad[first + i], e, out[first + i]);
    newton_lanes(lane, n, e, out + first);
    for (std::size_t i = 0; i < n; ++i)
      if (lane[i].active) out[first + i] = bracketed_solve(lane[i], e);
  }
}

kepler_solution solve_kepler(double mean_anomaly_rad, double e) noexcept {
  kepler_solution solution;
  solve_kepler(&mean_anomaly_rad, e, &solution, 1);
  return solution;
}

double eccentric_anomaly(double mean_anomaly_rad, double e) noexcept {
  return solve_kepler(mean_anomaly_rad, e).eccentric_anomaly_rad;
}

double true_anomaly_from_kepler(const kepler_solution& k, double e) noexcept {
  // tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2), with tan(E/2) = sin E / (1 + cos E) where cos E >= 0
  // and (1 - cos E) / sin E where cos E < 0: no cancellation on either side, so nu keeps the
  // half-angle form's relative accuracy up to e -> 1. Both arguments are scaled by the positive
  // 2 cos(E/2) (or 2 |sin(E/2)| for the second form, the sign of E moved to the numerator), so
  // atan2 returns nu/2 in [-pi/2, pi/2], the half-plane of E.
  const double numerator_scale = std::sqrt(1 + e), denominator_scale = std::sqrt(1 - e);
  double half_nu;
  if (k.cos_e >= 0) {
    half_nu = std::atan2(numerator_scale * k.sin_e, denominator_scale * (1 + k.cos_e));
  } else {
    const double sign = std::signbit(k.sin_e) ? -1.0 : 1.0;
    half_nu =
        std::atan2(sign * numerator_scale * (1 - k.cos_e), denominator_scale * std::abs(k.sin_e));
  }
  return k.turns_rad + 2 * half_nu;
}

double true_anomaly_from_eccentric(double eccentric_anomaly_rad, double e) noexcept {
  // Convert the principal angle in [-pi, pi], where cos(E/2) >= 0 keeps atan2 on the same
  // branch, then restore the whole turns that E carries.
  const double reduced = std::remainder(eccentric_anomaly_rad, 2 * pi<double>());
  const double half = reduced / 2;
  return (eccentric_anomaly_rad - reduced) +
         2 * std::atan2(std::sqrt(1 + e) * std::sin(half), std::sqrt(1 - e) * std::cos(half));
}

double eccentric_from_true_anomaly(double true_anomaly_rad, double e) noexcept {
  const double reduced = std::remainder(true_anomaly_rad, 2 * pi<double>());
  const double half = reduced / 2;
  return (true_anomaly_rad - reduced) +
         2 * std::atan2(std::sqrt(1 - e) * std::sin(half), std::sqrt(1 + e) * std::cos(half));
}

double orbital_period_s(double a_m, double gm_m3_s2) noexcept {
  return 2 * pi<double>() * std::sqrt(a_m * a_m * a_m / gm_m3_s2);
}

secular_rates two_body_rates(const elements& el, double gm_m3_s2) noexcept {
  return {0, 0, std::sqrt(gm_m3_s2 / (el.a_m * el.a_m * el.a_m))};
}

namespace {
// n J2 (R/p)^2, the common factor of the J2 secular rates.
double j2_factor(double a_m, double e, double gm_m3_s2, double j2, double r_eq_m) noexcept {
  const double n = std::sqrt(gm_m3_s2 / (a_m * a_m * a_m));
  const double p = a_m * (1 - e * e);
  return n * j2 * (r_eq_m / p) * (r_eq_m / p);
}
}  // namespace

secular_rates j2_secular_rates(const elements& el, double gm_m3_s2, double j2,
                               double r_eq_m) noexcept {
  const double n = std::sqrt(gm_m3_s2 / (el.a_m * el.a_m * el.a_m));
  const double k = j2_factor(el.a_m, el.e, gm_m3_s2, j2, r_eq_m);
  const double c = std::cos(el.i_rad);
  return {-1.5 * k * c, 0.75 * k * (5 * c * c - 1),
          n + 0.75 * k * std::sqrt(1 - el.e * el.e) * (3 * c * c - 1)};
}

double sun_synchronous_cos_inclination(double a_m, double e, double gm_m3_s2, double j2,
                                       double r_eq_m) noexcept {
  const double node_rate = 2 * pi<double>() / (tropical_year_days * 86400.0);
  return -node_rate / (1.5 * j2_factor(a_m, e, gm_m3_s2, j2, r_eq_m));
}

namespace {

struct perifocal_axes {
  vec3<double> p, q;  // unit vectors towards perigee and 90 deg ahead of it, ECI
};

// P, Q in ECI: R3(-Omega) R1(-i) R3(-omega).
perifocal_axes axes_of(double raan, double argp, double i) noexcept {
  const double co = std::cos(raan), so = std::sin(raan), cw = std::cos(argp), sw = std::sin(argp),
               ci = std::cos(i), si = std::sin(i);
  return {vec3<double>(co * cw - so * sw * ci, so * cw + co * sw * ci, sw * si),
          vec3<double>(-co * sw - so * cw * ci, -so * sw + co * cw * ci, cw * si)};
}

// Position and velocity of the osculating ellipse at a solution of Kepler's equation (MODEL §3).
orbit_state state_of(const elements& el, const perifocal_axes& axes, double gm_m3_s2,
                     const kepler_solution& kepler) noexcept {
  const double e = el.e;
  const double cos_e = kepler.cos_e, sin_e = kepler.sin_e;
  const double root = std::sqrt(1 - e * e);
  const double r = el.a_m * (1 - e * cos_e);
  // Perifocal position and velocity of the osculating ellipse.
  const double x = el.a_m * (cos_e - e), y = el.a_m * root * sin_e;
  const double speed = std::sqrt(gm_m3_s2 * el.a_m) / r;
  const double vx = -speed * sin_e, vy = speed * root * cos_e;
  return {scaled(axes.p, x) + scaled(axes.q, y), scaled(axes.p, vx) + scaled(axes.q, vy),
          true_anomaly_from_kepler(kepler, e)};
}

// The same at mean anomaly m.
orbit_state state_on(const elements& el, const perifocal_axes& axes, double gm_m3_s2,
                     double m) noexcept {
  return state_of(el, axes, gm_m3_s2, solve_kepler(m, el.e));
}

}  // namespace

orbit_state state_at(const elements& el, const secular_rates& rates, double gm_m3_s2,
                     double t_s) noexcept {
  const perifocal_axes axes =
      axes_of(el.raan_rad + rates.raan_dot * t_s, el.argp_rad + rates.argp_dot * t_s, el.i_rad);
  return state_on(el, axes, gm_m3_s2, el.m0_rad + rates.mean_anomaly_dot * t_s);
}

kepler_orbit::kepler_orbit(const elements& el, const secular_rates& rates, double gm_m3_s2) noexcept
    : elements_(el), rates_(rates), gm_(gm_m3_s2) {
  const perifocal_axes axes = axes_of(el.raan_rad, el.argp_rad, el.i_rad);
  p_axis_ = axes.p;
  q_axis_ = axes.q;
}

orbit_state kepler_orbit::state_at(double t_s) const noexcept {
  if (rates_.raan_dot != 0 || rates_.argp_dot != 0)
    return orbit::state_at(elements_, rates_, gm_, t_s);
  // Two-body: the orbit plane and the perigee stay put, their axes were computed once.
  return state_on(elements_, {p_axis_, q_axis_}, gm_,
                  elements_.m0_rad + rates_.mean_anomaly_dot * t_s);
}

void kepler_orbit::states_at(const double* t_s, orbit_state* out,
                             std::size_t count) const noexcept {
  if (rates_.raan_dot != 0 || rates_.argp_dot != 0) {
    for (std::size_t i = 0; i < count; ++i) out[i] = state_at(t_s[i]);
    return;
  }
  for (std::size_t first = 0; first < count; first += kepler_lanes) {
    const std::size_t n = std::min(kepler_lanes, count - first);
    double mean_anomaly[kepler_lanes];
    kepler_solution solution[kepler_lanes];
    for (std::size_t i = 0; i < n; ++i)
      mean_anomaly[i] = elements_.m0_rad + rates_.mean_anomaly_dot * t_s[first + i];
    solve_kepler(mean_anomaly, elements_.e, solution, n);
    for (std::size_t i = 0; i < n; ++i)
      out[first + i] = state_of(elements_, {p_axis_, q_axis_}, gm_, solution[i]);
  }
}

}  // namespace conescan::orbit
