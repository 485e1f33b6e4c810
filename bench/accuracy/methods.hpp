// The benchmark's methods end to end for one head sample (docs/PERFORMANCE.md): each is the core's
// sensor_head (include/conescan/sensor_head.hpp) with one truth step, except the paper's printed
// forms, which are a chain of the core's reference functions. The accuracy tests write the same
// chains from the core's steps themselves (tests/orbit/test_accuracy.cpp).
#pragma once

#include "accuracy/head_outcome.hpp"
#include "accuracy/method.hpp"
#include "accuracy/quartic_crossings.hpp"
#include "conescan/sensor_head.hpp"

namespace conescan::accuracy {

/// The paper's printed forms throughout: psi from Eq. (1)'s quadratic at the reference pulse,
/// the half chord from Eq. (3) with acos, eta_s from Eq. (6)'s quadratic ('+' root, whichever
/// root is the right one), then the sensed nadir as MODEL §6.
template <class T>
head_outcome<T> paper_quadratic_head(const head_sample<T>& s) noexcept {
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  if (!rho.ok()) return head_outcome<T>::failed(rho.state);
  const result<T> psi =
      misaligned_cone_angle_quadratic(s.optics.gamma, s.optics.sigma, T(-s.optics.phi_a));
  if (!psi.ok()) return head_outcome<T>::failed(psi.state);
  const result<T> half = half_chord_acos(psi.value, s.eta, rho.value);
  if (!half.ok()) return head_outcome<T>::failed(half.state);
  const crossings<T> measured{T(s.phi_n - half.value), T(s.phi_n + half.value), status::ok, 0};
  const result<T> eta_s =
      nadir_angle_from_chord_quadratic(s.optics.gamma, rho.value, measured.half_chord());
  if (!eta_s.ok()) return head_outcome<T>::failed(eta_s.state);
  return outcome_of(
      s, head_estimate<T>{eta_s.value,
                          direction_in_scan_frame(s.frame_body, eta_s.value, measured.phase()),
                          status::ok});
}

/// A head of the sample's optics, built per sample (each grid scene is a different head, and
/// the floor kernel too evaluates the head's trigonometry per sample).
template <class T>
sensor_head<T> head_of(const head_sample<T>& s) noexcept {
  return sensor_head<T>(s.frame_body, s.optics);
}

/// The stable closed forms: the bias model, then the processing.
template <class T>
head_outcome<T> stable_closed_form_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  const crossings<T> truth = head.bias_crossings(head.bias_cone_angle(), s.eta, s.phi_n, rho.value);
  return outcome_of(s, head.process(truth, disk_trig_of(s.radius_m, s.r_m)));
}

/// The scan model on the sphere in closed form, then the processing.
template <class T>
head_outcome<T> scan_sphere_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const disk_trig<T> disk = disk_trig_of(s.radius_m, s.r_m);
  const crossings<T> truth = head.scan_crossings(head.in_scan_frame(s.nadir_body), disk);
  return outcome_of(s, head.process(truth, disk));
}

/// The scan model on the sphere by bracketed Newton on the scan azimuth (the method the closed
/// form replaced), then the same processing.
template <class T>
head_outcome<T> scan_sphere_iterative_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  const crossings<T> truth =
      scan_model_crossings_sphere_iterative(s.optics, s.eta, s.phi_n, rho.value);
  return outcome_of(s, head.process(truth, disk_trig_of(s.radius_m, s.r_m)));
}

/// The ellipsoid seen from the sample's satellite, in body axes.
template <class T>
ellipsoid_horizon<T> surface_of(const head_sample<T>& s) noexcept {
  return ellipsoid_horizon_of(s.p_body_m, s.polar_body, s.a_eq_m, s.b_pol_m);
}

/// The sphere the ellipsoid methods' processing assumes: the equatorial radius seen from |p|
/// (MODEL §6's default on the ellipsoid).
template <class T>
disk_trig<T> equatorial_disk(const head_sample<T>& s) noexcept {
  return disk_trig_of(s.a_eq_m, T(norm(s.p_eci_m)));
}

/// The scan model on the ellipsoid (Newton on the scan circle), then the processing.
template <class T>
head_outcome<T> scan_ellipsoid_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const crossings<T> truth = head.scan_crossings(head.in_scan_frame(surface_of(s)));
  return outcome_of(s, head.process(truth, equatorial_disk(s)));
}

/// The same by bracketed Newton on the scan azimuth.
template <class T>
head_outcome<T> scan_ellipsoid_iterative_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const crossings<T> truth = scan_model_crossings_ellipsoid_iterative(
      s.optics, s.frame_eci, s.p_eci_m, s.a_eq_m, s.b_pol_m);
  return outcome_of(s, head.process(truth, equatorial_disk(s)));
}

/// The same by the quartic (quartic_crossings.hpp).
template <class T>
head_outcome<T> scan_ellipsoid_quartic_head(const head_sample<T>& s) noexcept {
  const sensor_head<T> head = head_of(s);
  const crossings<T> truth =
      quartic_crossings_ellipsoid(head.circle(), head.in_scan_frame(surface_of(s)));
  return outcome_of(s, head.process(truth, equatorial_disk(s)));
}

template <class T>
head_outcome<T> run_method(method m, const head_sample<T>& s) noexcept {
  switch (m) {
    case method::paper_quadratic:
      return paper_quadratic_head(s);
    case method::stable_closed_form:
      return stable_closed_form_head(s);
    case method::scan_sphere:
      return scan_sphere_head(s);
    case method::scan_sphere_iterative:
      return scan_sphere_iterative_head(s);
    case method::scan_ellipsoid:
      return scan_ellipsoid_head(s);
    case method::scan_ellipsoid_iterative:
      return scan_ellipsoid_iterative_head(s);
    case method::scan_ellipsoid_quartic:
      return scan_ellipsoid_quartic_head(s);
  }
  return head_outcome<T>::failed(status::invalid);
}

}  // namespace conescan::accuracy
