// The scan model (MODEL §5) by bracketed Newton on the scan azimuth phi, the method before the
// closed forms of scan_model.hpp: each crossing solves its own equation with psi = psi(phi), on a
// sphere or an ellipsoid. Kept as the closed forms' oracle in the tests, as the method they are
// measured against (bench/, docs/PERFORMANCE.md), and as the ellipsoid solver's fallback where
// its Newton iteration from the sphere does not settle (near miss, engulfed, grazing).
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/ellipsoid_horizon.hpp"
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
/// where h is lowest; each end is refined by bracketed_newton. The pair as found, its chord not
/// classified (solve_crossings does; the ellipsoid's fallback first asks whether the scan has a
/// second arc, MODEL §7). Statuses: miss (h <= 0 everywhere), engulfed (h >= 0 everywhere),
/// grazing (a far side on the horizon to within rounding, where a crossing is not determined),
/// ok.
template <class T, class Horizon>
crossings<T> solve_crossing_pair(const Horizon& h, T phi_c, const T& half_chord_guess) noexcept {
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
    return golden_section_maximum([&](const T& x) { return signed_h(x).value; },
                                  T(best - sample_step), T(best + sample_step), refine_steps)
        .x;
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
  return {in.x, out.x, status::ok, in.iterations + out.iterations};
}

/// solve_crossing_pair with the chord classified: grazing for a chord within
/// grazing_half_chord_min() of 0 or 2 pi.
template <class T, class Horizon>
crossings<T> solve_crossings(const Horizon& h, T phi_c, const T& half_chord_guess) noexcept {
  const crossings<T> c = solve_crossing_pair(h, phi_c, half_chord_guess);
  if (c.state != status::ok) return c;
  const status s = classify_half_chord(c.half_chord());
  return s == status::ok ? c : crossings<T>::failed(s);
}

/// Scan model on a sphere (MODEL §5) by bracketed Newton on the scan azimuth: the method before the
/// closed form (scan_model.hpp), kept to measure it against (bench/) and as the tests' oracle.
/// The line of sight at scan azimuth phi makes the angle
/// psi(phi) = misaligned_cone_angle(gamma, sigma, phi - phi_a) with S; it is on the horizon when
///   h(phi) = cos psi cos eta + sin psi sin eta cos(phi - phi_n) - cos rho = 0
/// (the cosine of its angle to the nadir minus cos rho; Eqs. (3) and (5) for any attitude).
///   eta, phi_n: true nadir's angle from S and azimuth about S (rad); rho: disk radius (rad).
/// Starts from the aligned closed form (psi = gamma); a phi_n beyond +-2 pi is first reduced to
/// (-pi, pi]. Domain: cone_in_domain, and
/// disk_geometry_in_domain(gamma, eta, rho); otherwise invalid. Accuracy: a few ulp of the
/// crossing azimuths (tests: tests/core/test_scan_model.cpp; docs/ACCURACY.md).
template <class T>
crossings<T> scan_model_crossings_sphere_iterative(const head_optics<T>& optics, const T& eta,
                                                   const T& phi_n, const T& rho) noexcept {
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

/// Scan model on an ellipsoid of revolution (MODEL §3, §5) by bracketed Newton on the scan
/// azimuth: the line of sight d(phi) = direction_in_scan_frame(frame, psi(phi), phi) crosses the
/// horizon where MODEL §5's tangency function g (ellipsoid_horizon.hpp) is 0 in front of the
/// satellite. `frame` holds the head's scan axes in the frame of `surface` (ECI, or the scan
/// frame itself: then e1, e2, e3 are the unit axes). The first guess is the aligned sphere
/// through the ellipsoid's radius along p. Domain: cone_in_domain, finite phi_a, surface ok;
/// otherwise invalid. Statuses: those of solve_crossings (ellipsoid_crossing_pair: of
/// solve_crossing_pair, the chord not classified). Accuracy: a few ulp of the azimuths;
/// tangency residual |g| below 1e-12 in double (tests/core/test_scan_model.cpp).
template <class T>
crossings<T> ellipsoid_crossing_pair(const head_optics<T>& optics, const scan_frame<T>& frame,
                                     const ellipsoid_horizon<T>& surface) noexcept {
  using std::asin;
  using std::atan2;
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a) ||
      surface.state != status::ok)
    return crossings<T>::failed(status::invalid);
  const vec3<T>&e1 = frame.e1, &e2 = frame.e2, &e3 = frame.e3;
  auto horizon = [&](const T& phi) {
    T phi_b = phi - optics.phi_a;
    T psi = misaligned_cone_angle(optics.gamma, optics.sigma, phi_b).value;
    T slope_psi = misaligned_cone_angle_slope(optics.sigma, phi_b, psi);
    T cos_psi = cos(psi), sin_psi = sin(psi), cos_phi = cos(phi), sin_phi = sin(phi);
    vec3<T> radial = scaled(e1, cos_phi) + scaled(e2, sin_phi);
    vec3<T> d = scaled(e3, cos_psi) + scaled(radial, sin_psi);
    vec3<T> d_slope = scaled(scaled(e3, T(-sin_psi)) + scaled(radial, cos_psi), slope_psi) +
                      scaled(scaled(e2, cos_phi) - scaled(e1, sin_phi), sin_psi);
    value_slope<T> v{T(0), T(0)};
    ellipsoid_tangency(surface, d, d_slope, v.value, v.slope);
    return v;
  };
  // The ellipsoid's centre direction is -p, i.e. -q up to the stretch along the axis; -q's
  // direction is not needed exactly, only an azimuth on the Earth to start from.
  const vec3<T> centre = -surface.q;
  const T eta_c = angle_between(e3, centre);
  const T phi_c = atan2(dot(centre, e2), dot(centre, e1));
  const T guess = half_chord(optics.gamma, eta_c, T(asin(surface.inverse_norm_p_scaled))).value;
  return solve_crossing_pair(horizon, phi_c, guess);
}

template <class T>
crossings<T> scan_model_crossings_ellipsoid_iterative(
    const head_optics<T>& optics, const scan_frame<T>& frame,
    const ellipsoid_horizon<T>& surface) noexcept {
  const crossings<T> c = ellipsoid_crossing_pair(optics, frame, surface);
  if (c.state != status::ok) return c;
  const status s = classify_half_chord(c.half_chord());
  return s == status::ok ? c : crossings<T>::failed(s);
}

/// The same with the frame in ECI and the ellipsoid's polar axis along ECI z: the satellite at
/// p_eci (m, from the ellipsoid's centre), semi-axes a_eq, b_pol (m), oblate or prolate.
/// `frame_eci` itself is not checked: pass a valid frame.
template <class T>
crossings<T> scan_model_crossings_ellipsoid_iterative(const head_optics<T>& optics,
                                                      const scan_frame<T>& frame_eci,
                                                      const vec3<T>& p_eci, const T& a_eq,
                                                      const T& b_pol) noexcept {
  return scan_model_crossings_ellipsoid_iterative(
      optics, frame_eci, ellipsoid_horizon_of(p_eci, vec3<T>(T(0), T(0), T(1)), a_eq, b_pol));
}

}  // namespace conescan
