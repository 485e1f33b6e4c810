// The exact forward model: every crossing solves its own equation with psi = psi(phi) (SPEC §5,
// "scan"), on a sphere or on the inflated WGS84 ellipsoid.
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/root_finding.hpp"
#include "conescan/scan_frame.hpp"

namespace conescan {

/// Samples of the whole scan circle taken when the disk centre's azimuth does not lie on the
/// Earth (or its opposite does); the golden-section search then refines the best sample.
inline constexpr int extreme_search_samples = 64;

/// Two crossings of a horizon function h(phi) (positive on the Earth, negative off it) given the
/// azimuth phi_c of the disk centre and a first guess of the half chord (the aligned closed
/// form; NaN if none). The arc on the Earth is found between phi_c and the point opposite it,
/// where h is lowest; each end is refined by bracketed_newton.
/// Statuses: miss (h <= 0 everywhere), engulfed (h >= 0 everywhere), grazing (a chord within
/// grazing_half_chord_min() of 0 or 2 pi, or a far side on the horizon to within rounding, where
/// a crossing is not determined), ok.
template <class T, class Horizon>
crossings<T> solve_crossings(const Horizon& h, T phi_c, const T& half_chord_guess) noexcept {
  const T two_pi = T(2) * pi<T>();
  const T sample_step = two_pi / T(extreme_search_samples);
  const int refine_steps = std::numeric_limits<T>::digits / 2 + 8;
  auto extreme = [&](bool highest) {
    auto signed_h = [&](const T& phi) {
      value_slope<T> v = h(phi);
      return value_slope<T>{highest ? v.value : T(-v.value), v.slope};
    };
    T best = phi_c;
    T best_value = signed_h(phi_c).value;
    for (int i = 1; i < extreme_search_samples; ++i) {
      T phi = phi_c + T(i) * sample_step;
      T v = signed_h(phi).value;
      if (v > best_value) {
        best = phi;
        best_value = v;
      }
    }
    return golden_section_max(signed_h, T(best - sample_step), T(best + sample_step), refine_steps);
  };

  if (!(h(phi_c).value > T(0))) {
    phi_c = extreme(true);
    if (!(h(phi_c).value > T(0))) return crossings<T>::failed(status::miss);
  }
  T phi_far = phi_c + pi<T>();
  T h_far = h(phi_far).value;
  if (!(h_far < T(0))) {
    phi_far = extreme(false);
    if (!(h(phi_far).value < T(0))) return crossings<T>::failed(status::engulfed);
    phi_far = phi_c + wrap_two_pi(T(phi_far - phi_c));  // in (phi_c, phi_c + 2 pi)
    h_far = h(phi_far).value;
  }
  // Both brackets need a sign change at the very points passed to bracketed_newton. h is 2 pi
  // periodic only up to rounding: where the far side skims the horizon (the line of sight
  // passes through S with S on the horizon), h(phi_far) and h(phi_far - 2 pi) may differ in
  // sign, and the crossing there is not determined (a fuzzing finding: float returned an
  // Earth-in azimuth where h = 0.38, status ok). Such a scan is grazing.
  if (!(h_far < T(0)) || !(h(T(phi_far - two_pi)).value < T(0)))
    return crossings<T>::failed(status::grazing);
  T guess = is_finite(half_chord_guess) ? half_chord_guess : (phi_far - phi_c) / T(2);
  root<T> out = bracketed_newton(h, phi_c, phi_far, T(phi_c + guess));
  root<T> in = bracketed_newton(h, T(phi_far - two_pi), phi_c, T(phi_c - guess));
  crossings<T> c{in.x, out.x, status::ok, in.iterations + out.iterations};
  status s = classify_half_chord(c.half_chord());
  return s == status::ok ? c : crossings<T>::failed(s);
}

/// Scan model on a sphere (SPEC §5). The line of sight at scan azimuth phi makes the angle
/// psi(phi) = misaligned_cone_angle(gamma, sigma, phi - phi_a) with S; it is on the horizon when
///   h(phi) = cos psi cos eta + sin psi sin eta cos(phi - phi_n) - cos rho = 0
/// (the cosine of its angle to the nadir minus cos rho; Eqs. (3) and (5) for any attitude).
///   eta, phi_n: true nadir's angle from S and azimuth about S (rad); rho: disk radius (rad).
/// Starts from the aligned closed form (psi = gamma); a phi_n beyond +-2 pi is first reduced to
/// (-pi, pi]. Domain: cone_in_domain, and
/// disk_geometry_in_domain(gamma, eta, rho); otherwise invalid. Accuracy: a few ulp of the
/// crossing azimuths (tests: tests/test_scan_model.cpp; docs/ACCURACY.md).
template <class T>
crossings<T> scan_model_crossings_sphere(const head_optics<T>& optics, const T& eta, const T& phi_n,
                                         const T& rho) noexcept {
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a) ||
      !is_finite(phi_n) || !disk_geometry_in_domain(optics.gamma, eta, rho))
    return crossings<T>::failed(status::invalid);
  // As in bias_model_crossings: whole turns of phi_n would eat the azimuths' digits.
  using std::abs;
  const T centre = abs(phi_n) <= T(2) * pi<T>() ? phi_n : wrap_pi(phi_n);
  const T cos_eta = cos(eta), sin_eta = sin(eta), cos_rho = cos(rho);
  auto horizon = [&](const T& phi) {
    T phi_b = phi - optics.phi_a;
    T psi = misaligned_cone_angle(optics.gamma, optics.sigma, phi_b).value;
    T slope_psi = misaligned_cone_angle_slope(optics.sigma, phi_b, psi);
    T cos_psi = cos(psi), sin_psi = sin(psi);
    T cos_dphi = cos(phi - centre), sin_dphi = sin(phi - centre);
    return value_slope<T>{cos_psi * cos_eta + sin_psi * sin_eta * cos_dphi - cos_rho,
                          slope_psi * (cos_psi * sin_eta * cos_dphi - sin_psi * cos_eta) -
                              sin_psi * sin_eta * sin_dphi};
  };
  result<T> aligned = half_chord(optics.gamma, eta, rho);
  return solve_crossings(horizon, centre, aligned.value);
}

/// Scan model on an ellipsoid of revolution about ECI z (SPEC §3, §5): semi-axes a_eq
/// (equatorial) and b_pol (polar), in metres, e.g. WGS84 a + h_h and b + h_h (oblate) or an
/// apparent horizon surface (issue 7; may be prolate). The satellite is at p_eci (m) relative to
/// the ellipsoid's centre; `frame_eci` holds the head's scan frame expressed in ECI. With x, y
/// scaled by 1/a_eq and z by 1/b_pol to P and D, the line of sight d(phi) hits the ellipsoid iff
///   g = (P.D)^2 - |D|^2 (|P|^2 - 1) >= 0 with P.D < 0,
/// and the crossings are the zeros of g (taken as -|D|^2 (|P|^2 - 1) where P.D >= 0, which is
/// continuous and negative there). The first guess is the aligned sphere of radius a_eq about
/// the direction to the centre. Domain: cone_in_domain, a_eq, b_pol > 0 finite, satellite
/// outside the ellipsoid (|P| > 1); otherwise invalid. Accuracy: a few ulp of the azimuths;
/// tangency residual |g| below 1e-12 in double (tests/test_scan_model.cpp).
template <class T>
crossings<T> scan_model_crossings_ellipsoid(const head_optics<T>& optics,
                                            const scan_frame<T>& frame_eci, const vec3<T>& p_eci,
                                            const T& a_eq, const T& b_pol) noexcept {
  using std::asin;
  using std::atan2;
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a) || !is_finite(a_eq) ||
      !is_finite(b_pol) || !(b_pol > T(0)) || !(a_eq > T(0)) || !is_finite(p_eci.x) ||
      !is_finite(p_eci.y) || !is_finite(p_eci.z))
    return crossings<T>::failed(status::invalid);
  auto to_unit_sphere = [&](const vec3<T>& v) {
    return vec3<T>(v.x / a_eq, v.y / a_eq, v.z / b_pol);
  };
  const vec3<T> p = to_unit_sphere(p_eci);
  const vec3<T> e1 = to_unit_sphere(frame_eci.e1), e2 = to_unit_sphere(frame_eci.e2),
                e3 = to_unit_sphere(frame_eci.e3);
  const T height_term = dot(p, p) - T(1);
  if (!(height_term > T(0))) return crossings<T>::failed(status::invalid);
  auto horizon = [&](const T& phi) {
    T phi_b = phi - optics.phi_a;
    T psi = misaligned_cone_angle(optics.gamma, optics.sigma, phi_b).value;
    T slope_psi = misaligned_cone_angle_slope(optics.sigma, phi_b, psi);
    T cos_psi = cos(psi), sin_psi = sin(psi), cos_phi = cos(phi), sin_phi = sin(phi);
    vec3<T> radial = scaled(e1, cos_phi) + scaled(e2, sin_phi);
    vec3<T> d = scaled(e3, cos_psi) + scaled(radial, sin_psi);
    vec3<T> d_slope = scaled(scaled(e3, T(-sin_psi)) + scaled(radial, cos_psi), slope_psi) +
                      scaled(scaled(e2, cos_phi) - scaled(e1, sin_phi), sin_psi);
    T pd = dot(p, d);
    T dd = dot(d, d);
    T value = -dd * height_term;
    T slope = T(-2) * dot(d, d_slope) * height_term;
    if (pd < T(0)) {
      value += pd * pd;
      slope += T(2) * pd * dot(p, d_slope);
    }
    return value_slope<T>{value, slope};
  };
  const vec3<T> centre = -p_eci;
  T eta_c = angle_between(frame_eci.e3, centre);
  T phi_c = atan2(dot(centre, frame_eci.e2), dot(centre, frame_eci.e1));
  T r = norm(p_eci);
  T guess = not_a_number<T>();
  if (a_eq < r) guess = half_chord(optics.gamma, eta_c, T(asin(a_eq / r))).value;
  return solve_crossings(horizon, phi_c, guess);
}

}  // namespace conescan
