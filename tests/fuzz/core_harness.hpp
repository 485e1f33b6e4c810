// Fuzz harness of the core routines (MODEL §7): any scalars in, a status out, and every ok value
// finite and in its documented range; every failed value NaN; every iteration bounded.
//
// The first byte picks the scalar type, the second the routine; the rest become its inputs
// (byte_reader::draw). check_core returns "" when every invariant holds, else what broke and
// the inputs. fuzz_core.cpp aborts on a failure; tests/apps/test_robustness.cpp replays the corpus.
#pragma once

#include <array>
#include <string>

#include "conescan/conescan.hpp"
#include "fuzz/byte_reader.hpp"
#include "orbit/kepler.hpp"

namespace conescan_fuzz {

template <class T>
struct core_checker {
  byte_reader& in;
  const char* type;
  const char* routine = "";

  // A few hundred ulp of values of order one: rounding, not a wrong branch.
  static T tol() { return T(256) * std::numeric_limits<T>::epsilon(); }
  static bool finite(const T& x) { return conescan::is_finite(x); }
  static bool nan(const T& x) { return x != x; }
  static T abs(const T& x) { return x < T(0) ? -x : x; }
  static T pi() { return conescan::pi<T>(); }

  std::string fail(const std::string& what) { return failure(routine, type, what, in.drawn()); }

  template <class R>
  std::string check_failed_result(const R& r) {
    if (r.ok()) return {};
    if (!nan(r.value)) return fail("a failed result carries a number, not NaN");
    return {};
  }

  std::string check_crossings(const conescan::crossings<T>& c, int max_iterations) {
    using conescan::status;
    if (c.iterations < 0 || c.iterations > max_iterations)
      return fail("iterations " + std::to_string(c.iterations) + " outside [0, " +
                  std::to_string(max_iterations) + "]");
    if (c.state != status::ok) {
      if (!nan(c.phi_in) || !nan(c.phi_out)) return fail("failed crossings carry numbers");
      return {};
    }
    if (!finite(c.phi_in) || !finite(c.phi_out)) return fail("ok crossings are not finite");
    const T graze = conescan::grazing_half_chord_min<T>();
    const T half = c.half_chord();
    if (!(half >= graze - tol() && half <= pi() - graze + tol()))
      return fail("ok half chord outside [grazing min, pi - grazing min]");
    return {};
  }

  // misaligned_cone_angle, its quadratic form and its slope. The line of sight makes gamma
  // with A, which is sigma from S: |psi - gamma| <= sigma (triangle inequality).
  std::string cone_angle() {
    const T gamma = draw<T>(in), sigma = draw<T>(in), phi_b = draw<T>(in);
    const bool domain = conescan::cone_in_domain(gamma, sigma) && finite(phi_b);
    for (int form = 0; form < 2; ++form) {
      routine = form == 0 ? "misaligned_cone_angle" : "misaligned_cone_angle_quadratic";
      const conescan::result<T> psi =
          form == 0 ? conescan::misaligned_cone_angle(gamma, sigma, phi_b)
                    : conescan::misaligned_cone_angle_quadratic(gamma, sigma, phi_b);
      // The quadratic form is also invalid where cos psi rounds to 1 (psi <= gamma + sigma
      // tiny, or gamma - sigma tiny at phi_b near 0): acos has no digit of psi left there.
      const bool acos_resolves = form == 0 || gamma - sigma > T(4) * sqrt_tol();
      if (psi.ok() && !domain) return fail("status ok outside the documented domain");
      if (!psi.ok() && domain && acos_resolves)
        return fail("status not ok inside the documented domain");
      if (auto f = check_failed_result(psi); !f.empty()) return f;
      if (!psi.ok()) continue;
      if (!finite(psi.value)) return fail("ok psi is not finite");
      // (The stable form may round gamma - sigma to 0 at phi_b = pi: an absolute error of
      // rounding. The quadratic form returned 0 for a denormal gamma, a relative error of 1.)
      if (form == 1 && !(psi.value > T(0))) return fail("ok psi is not positive");
      // The quadratic form's acos loses half the digits as psi -> 0: sqrt(tol) there.
      const T slack = form == 0 ? tol() : T(64) * sqrt_tol();
      if (!(abs(psi.value - gamma) <= sigma + slack)) return fail("|psi - gamma| > sigma");
      // The slope's denominator -R sin(spread) is negative on the domain, but rounds to 0 as
      // sigma -> gamma at phi_b = +-90 deg (the solver then bisects): finite well inside.
      if (form == 0 && sigma <= gamma / T(2)) {
        routine = "misaligned_cone_angle_slope";
        if (!finite(conescan::misaligned_cone_angle_slope(sigma, phi_b, psi.value)))
          return fail("slope not finite for sigma <= gamma / 2");
      }
    }
    return {};
  }

  static T sqrt_tol() {
    using std::sqrt;
    return sqrt(std::numeric_limits<T>::epsilon());
  }

  std::string half_chord() {
    const T psi = draw<T>(in), eta = draw<T>(in), rho = draw<T>(in);
    for (int form = 0; form < 2; ++form) {
      routine = form == 0 ? "half_chord" : "half_chord_acos";
      const conescan::result<T> phi = form == 0 ? conescan::half_chord(psi, eta, rho)
                                                : conescan::half_chord_acos(psi, eta, rho);
      if (phi.ok() && !conescan::disk_geometry_in_domain(psi, eta, rho))
        return fail("ok outside the domain");
      if (auto f = check_failed_result(phi); !f.empty()) return f;
      if (!phi.ok()) continue;
      const T graze = conescan::grazing_half_chord_min<T>();
      if (!(finite(phi.value) && phi.value >= graze && phi.value <= pi() - graze))
        return fail("ok Phi outside [grazing min, pi - grazing min]");
    }
    return {};
  }

  std::string disk() {
    routine = "disk_angular_radius";
    const T radius = draw<T>(in), r = draw<T>(in);
    const conescan::result<T> rho = conescan::disk_angular_radius(radius, r);
    if (auto f = check_failed_result(rho); !f.empty()) return f;
    if (rho.ok() && !(finite(rho.value) && rho.value > T(0) && rho.value <= pi() / T(2)))
      return fail("ok rho outside (0, pi/2]");
    return {};
  }

  std::string inversion() {
    using std::cos;
    using std::sin;
    const T gamma = draw<T>(in), rho_p = draw<T>(in), half = draw<T>(in), eta0 = draw<T>(in);
    routine = "nadir_angle_roots_from_chord";
    const conescan::nadir_angle_roots<T> roots =
        conescan::nadir_angle_roots_from_chord(gamma, rho_p, half);
    if (roots.state == conescan::status::ok) {
      if (!(finite(roots.plus) && finite(roots.minus) && finite(roots.half_separation)))
        return fail("ok roots not finite");
      if (!(roots.half_separation >= T(0) && roots.half_separation <= pi() &&
            roots.plus >= roots.minus))
        return fail("ok roots out of order or half separation outside [0, pi]");
    } else if (!nan(roots.plus) || !nan(roots.minus)) {
      return fail("failed roots carry numbers");
    }
    routine = "nadir_angle_from_chord";
    const conescan::result<T> eta = conescan::nadir_angle_from_chord(gamma, rho_p, half, eta0);
    if (auto f = check_failed_result(eta); !f.empty()) return f;
    if (eta.ok()) {
      if (!finite(eta.value)) return fail("ok eta_s not finite");
      // Eq. (5) must hold at the root: cos rho_p = cos gamma cos eta + sin gamma sin eta cos Phi.
      const T residual =
          cos(gamma) * cos(eta.value) + sin(gamma) * sin(eta.value) * cos(half) - cos(rho_p);
      if (!(abs(residual) <= tol())) return fail("ok eta_s does not solve Eq. (5)");
    }
    routine = "nadir_angle_from_chord_quadratic";
    const conescan::result<T> eta_q =
        conescan::nadir_angle_from_chord_quadratic(gamma, rho_p, half);
    if (auto f = check_failed_result(eta_q); !f.empty()) return f;
    if (eta_q.ok() && !(finite(eta_q.value) && eta_q.value >= T(0) && eta_q.value <= pi()))
      return fail("ok eta_s outside [0, pi]");
    return {};
  }

  conescan::head_optics<T> optics() {
    const T gamma = draw<T>(in), sigma = draw<T>(in), phi_a = draw<T>(in);
    return {gamma, sigma, phi_a};
  }

  std::string bias() {
    routine = "bias_model_crossings";
    const conescan::head_optics<T> o = optics();
    const T eta = draw<T>(in), phi_n = draw<T>(in), rho = draw<T>(in);
    const conescan::crossings<T> c = conescan::bias_model_crossings(o, eta, phi_n, rho);
    if (auto f = check_crossings(c, 0); !f.empty()) return f;
    // Beyond one turn phi_n is reduced modulo 2 pi first.
    if (c.state == conescan::status::ok && abs(phi_n) <= T(2) * pi() &&
        !(abs(c.phase() - phi_n) <= T(4) * tol()))
      return fail("bias model phase differs from phi_n");
    return {};
  }

  static int scan_iteration_cap() {
    // Two bracketed_newton calls of the crossing solver.
    return 2 * conescan::bracketed_newton_max_iterations<T>();
  }

  std::string scan_sphere() {
    using std::cos;
    using std::sin;
    routine = "scan_model_crossings_sphere";
    const conescan::head_optics<T> o = optics();
    const T eta = draw<T>(in), phi_n = draw<T>(in), rho = draw<T>(in);
    const conescan::crossings<T> c = conescan::scan_model_crossings_sphere(o, eta, phi_n, rho);
    if (auto f = check_crossings(c, scan_iteration_cap()); !f.empty()) return f;
    if (c.state != conescan::status::ok || !(abs(phi_n) <= T(2) * pi())) return {};
    // Each crossing lies on the horizon: h(phi) = 0 up to rounding of h and of phi, i.e. within
    // |h'| times a few ulp of phi. Where h' is not finite (the line of sight passes through S as
    // sigma -> gamma, and psi(phi) has a kink) the root is ill-conditioned: not checked.
    for (const T phi : {c.phi_in, c.phi_out}) {
      const T phi_b = phi - o.phi_a;
      const T psi = conescan::misaligned_cone_angle(o.gamma, o.sigma, phi_b).value;
      const T slope_psi = conescan::misaligned_cone_angle_slope(o.sigma, phi_b, psi);
      const T h = cos(psi) * cos(eta) + sin(psi) * sin(eta) * cos(phi - phi_n) - cos(rho);
      const T h_slope = slope_psi * (cos(psi) * sin(eta) * cos(phi - phi_n) - sin(psi) * cos(eta)) -
                        sin(psi) * sin(eta) * sin(phi - phi_n);
      if (!finite(h_slope)) continue;
      const T scale = T(1) + abs(phi) + abs(phi_n) + abs(o.phi_a);
      if (!(abs(h) <= T(16) * tol() * scale * (T(1) + abs(h_slope))))
        return fail("a crossing is off the horizon");
    }
    return {};
  }

  std::string scan_ellipsoid() {
    routine = "scan_model_crossings_ellipsoid";
    const conescan::head_optics<T> o = optics();
    const T alpha = draw<T>(in), beta = draw<T>(in);
    const conescan::vec3<T> p(draw<T>(in), draw<T>(in), draw<T>(in));
    const T a_eq = draw<T>(in), b_pol = draw<T>(in);
    const conescan::scan_frame<T> frame = conescan::scan_frame_from_mounting(alpha, beta);
    const conescan::crossings<T> c =
        conescan::scan_model_crossings_ellipsoid(o, frame, p, a_eq, b_pol);
    return check_crossings(c, scan_iteration_cap());
  }

  std::string frame() {
    routine = "scan_frame_from_mounting";
    const T alpha = draw<T>(in), beta = draw<T>(in), psi = draw<T>(in), phi = draw<T>(in);
    const conescan::scan_frame<T> f = conescan::scan_frame_from_mounting(alpha, beta);
    if (f.state != conescan::status::ok) {
      if (!nan(f.e3.x)) return fail("failed frame carries numbers");
      return {};
    }
    const T big_tol = T(16) * tol();
    using conescan::dot;
    if (!(abs(dot(f.e1, f.e1) - T(1)) <= big_tol && abs(dot(f.e2, f.e2) - T(1)) <= big_tol &&
          abs(dot(f.e3, f.e3) - T(1)) <= big_tol && abs(dot(f.e1, f.e2)) <= big_tol &&
          abs(dot(f.e2, f.e3)) <= big_tol && abs(dot(f.e3, f.e1)) <= big_tol))
      return fail("ok frame not orthonormal");
    routine = "direction_in_scan_frame";
    const conescan::vec3<T> d = conescan::direction_in_scan_frame(f, psi, phi);
    if (finite(psi) && finite(phi) && !(abs(dot(d, d) - T(1)) <= big_tol))
      return fail("direction not a unit vector");
    return {};
  }

  std::string head() {
    routine = "process_head";
    const T alpha = draw<T>(in), beta = draw<T>(in), gamma = draw<T>(in), rho_p = draw<T>(in);
    const T phi_in = draw<T>(in), phi_out = draw<T>(in);
    const conescan::status state =
        in.pick(2) ? conescan::status::ok : static_cast<conescan::status>(in.pick(7));
    const conescan::scan_frame<T> f = conescan::scan_frame_from_mounting(alpha, beta);
    const conescan::crossings<T> measured{phi_in, phi_out, state, 0};
    const conescan::head_estimate<T> e = conescan::process_head(f, gamma, rho_p, measured);
    if (e.state != conescan::status::ok) {
      if (!nan(e.eta_s) || !nan(e.nadir.x)) return fail("failed estimate carries numbers");
      return {};
    }
    if (!(finite(e.eta_s) && finite(e.nadir.x) && finite(e.nadir.y) && finite(e.nadir.z)))
      return fail("ok estimate not finite");
    if (!(abs(conescan::dot(e.nadir, e.nadir) - T(1)) <= T(16) * tol()))
      return fail("ok sensed nadir not a unit vector");
    return {};
  }

  // process_head with its own eta0, then the measurement errors applied to the crossings.
  std::string head_with_errors() {
    if (std::string f = head(); !f.empty()) return f;
    routine = "process_head (eta0 given)";
    const T alpha = draw<T>(in), beta = draw<T>(in), gamma = draw<T>(in), rho_p = draw<T>(in);
    const T phi_in = draw<T>(in), phi_out = draw<T>(in), eta0 = draw<T>(in);
    const conescan::scan_frame<T> f = conescan::scan_frame_from_mounting(alpha, beta);
    const conescan::crossings<T> measured{phi_in, phi_out, conescan::status::ok, 0};
    const conescan::head_estimate<T> e = conescan::process_head(f, gamma, rho_p, measured, eta0);
    if (e.state == conescan::status::ok &&
        !(finite(e.eta_s) && finite(e.nadir.x) && finite(e.nadir.y) && finite(e.nadir.z)))
      return fail("ok estimate not finite");
    if (e.state != conescan::status::ok && !(nan(e.eta_s) && nan(e.nadir.x)))
      return fail("failed estimate carries numbers");
    // The measurement errors act on crossings a forward model returned: ok ones are finite
    // with a chord in (0, 2 pi).
    if (!check_measured(measured).empty()) return {};
    return measurement_errors(measured);
  }

  // with_crossing_noise and quantised: an ok result has finite azimuths and a chord in
  // (0, 2 pi); the quantised phase lies in (-pi, pi] on the lsb grid; a failed one is NaN.
  std::string measurement_errors(const conescan::crossings<T>& c) {
    const T noise_in = draw<T>(in), noise_out = draw<T>(in), lsb = draw<T>(in);
    routine = "with_crossing_noise";
    const conescan::crossings<T> noisy = conescan::with_crossing_noise(c, noise_in, noise_out);
    if (std::string f = check_measured(noisy); !f.empty()) return f;
    routine = "quantised";
    const conescan::crossings<T> q = conescan::quantised(c, lsb);
    if (std::string f = check_measured(q); !f.empty()) return f;
    if (q.state == conescan::status::ok && lsb > T(0)) {
      using std::round;
      const T phase = q.phase(), steps = phase / lsb;
      if (!(phase > -pi() - tol() && phase <= pi() + tol()))
        return fail("quantised phase outside (-pi, pi]");
      if (!(abs(steps - round(steps)) <= T(1e-3) + tol() * abs(steps)))
        return fail("quantised phase off the lsb grid");
    }
    return {};
  }

  std::string check_measured(const conescan::crossings<T>& c) {
    if (c.state != conescan::status::ok)
      return nan(c.phi_in) && nan(c.phi_out) ? std::string()
                                             : fail("failed crossings carry numbers");
    if (!(finite(c.phi_in) && finite(c.phi_out))) return fail("ok crossings not finite");
    if (!(c.chord() > T(0) && c.chord() < T(2) * pi())) return fail("ok chord outside (0, 2 pi)");
    return {};
  }

  std::string combine() {
    routine = "combine_heads";
    std::array<conescan::head_estimate<T>, 4> heads{};
    const unsigned n = in.pick(5);
    for (unsigned k = 0; k < n; ++k) {
      heads[k].eta_s = draw<T>(in);
      heads[k].nadir = conescan::vec3<T>(draw<T>(in), draw<T>(in), draw<T>(in));
      heads[k].state = in.pick(2) ? conescan::status::ok : conescan::status::miss;
    }
    const conescan::head_estimate<T> s =
        conescan::combine_heads<T>(heads.begin(), heads.begin() + n);
    if (s.state != conescan::status::ok) {
      if (!nan(s.nadir.x)) return fail("failed system solution carries numbers");
      return {};
    }
    if (!(finite(s.nadir.x) && finite(s.nadir.y) && finite(s.nadir.z)))
      return fail("ok system nadir not finite");
    return {};
  }

  std::string wraps() {
    const T x = draw<T>(in);
    routine = "wrap_pi";
    const T w = conescan::wrap_pi(x);
    if (finite(x) && !(w > -pi() && w <= pi())) return fail("wrap_pi outside (-pi, pi]");
    if (!finite(x) && !nan(w)) return fail("wrap_pi of a non-finite value is a number");
    routine = "wrap_two_pi";
    const T w2 = conescan::wrap_two_pi(x);
    if (finite(x) && !(w2 >= T(0) && w2 < T(2) * pi()))
      return fail("wrap_two_pi outside [0, 2 pi)");
    routine = "classify_half_chord";
    const conescan::status s = conescan::classify_half_chord(x);
    const T graze = conescan::grazing_half_chord_min<T>();
    if (s == conescan::status::ok && !(x >= graze && x <= pi() - graze))
      return fail("classify_half_chord ok outside its range");
    return {};
  }

  std::string attitude() {
    routine = "roll_pitch_from_nadir";
    const conescan::vec3<T> n(draw<T>(in), draw<T>(in), draw<T>(in));
    const conescan::roll_pitch<T> rp = conescan::roll_pitch_from_nadir(n);
    if (finite(n.x) && finite(n.y) && finite(n.z)) {
      if (!(finite(rp.roll) && finite(rp.pitch))) return fail("roll/pitch of a finite n");
      if (!(abs(rp.roll) <= pi() && abs(rp.pitch) <= pi() / T(2) + tol()))
        return fail("roll or pitch out of range");
    }
    routine = "nadir_in_body";
    const T roll = draw<T>(in), pitch = draw<T>(in);
    const conescan::vec3<T> nb = conescan::nadir_in_body(roll, pitch);
    if (finite(roll) && finite(pitch) && !(abs(conescan::dot(nb, nb) - T(1)) <= T(16) * tol()))
      return fail("nadir_in_body not a unit vector");
    return {};
  }

  std::string run() {
    // One check per input, drawn as before: its byte modulo the number of checks.
    using check = std::string (core_checker::*)();
    static constexpr check checks[] = {
        &core_checker::cone_angle,     &core_checker::half_chord, &core_checker::disk,
        &core_checker::inversion,      &core_checker::bias,       &core_checker::scan_sphere,
        &core_checker::scan_ellipsoid, &core_checker::frame,      &core_checker::head_with_errors,
        &core_checker::combine,        &core_checker::wraps,      &core_checker::attitude};
    return (this->*checks[in.pick(static_cast<unsigned>(std::size(checks)))])();
  }
};

/// Kepler's equation (orbit layer, double): any finite M, e in [0, 1) -> a finite E solving it.
inline std::string check_kepler(byte_reader& in) {
  const double m = draw<double>(in), e = draw<double>(in);
  if (!(std::isfinite(m) && e >= 0 && e < 1)) return {};
  const double ecc = conescan::orbit::eccentric_anomaly(m, e);
  if (!std::isfinite(ecc))
    return failure("eccentric_anomaly", "double", "E not finite", in.drawn());
  // Below 1e6 rad the residual is rounding; above, ulp(M) itself exceeds the turn's detail.
  if (std::abs(m) < 1e6) {
    const double residual = ecc - e * std::sin(ecc) - m;
    if (!(std::abs(residual) <= 64 * 0x1p-52 * (1 + std::abs(m))))
      return failure("eccentric_anomaly", "double", "E does not solve Kepler's equation",
                     in.drawn());
  }
  const double nu = conescan::orbit::true_anomaly_from_eccentric(ecc, e);
  if (!std::isfinite(nu))
    return failure("true_anomaly_from_eccentric", "double", "nu not finite", in.drawn());
  return {};
}

/// The whole harness: "" when every invariant held.
inline std::string check_core(const std::uint8_t* data, std::size_t size) {
  byte_reader in(data, size);
  switch (in.pick(4)) {
    case 0:
      return core_checker<float>{in, "float"}.run();
    case 1:
      return core_checker<long double>{in, "long double"}.run();
    case 2:
      return check_kepler(in);
    default:
      return core_checker<double>{in, "double"}.run();
  }
}

}  // namespace conescan_fuzz
