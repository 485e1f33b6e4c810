// One head end to end for each method: forward model -> crossings -> processing -> roll/pitch
// (SPEC §5, §6). These are the functions the benchmark times and the accuracy tests check.
#pragma once

#include "accuracy/head_sample.hpp"
#include "accuracy/method.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_model.hpp"

namespace conescan::accuracy {

/// What one head senses (rad). The true attitude is zero, so roll and pitch are the errors.
template <class T>
struct head_outcome {
  T eta_err;  ///< eta_s - eta, sensed minus true (SPEC §1)
  T roll;
  T pitch;
  status state;

  static head_outcome failed(status s) noexcept {
    return {not_a_number<T>(), not_a_number<T>(), not_a_number<T>(), s};
  }
};

template <class T>
head_outcome<T> outcome_of(const head_sample<T>& s, const head_estimate<T>& estimate) noexcept {
  if (estimate.state != status::ok) return head_outcome<T>::failed(estimate.state);
  const roll_pitch<T> sensed = roll_pitch_from_nadir(estimate.nadir);
  return {T(estimate.eta_s - s.eta), sensed.roll, sensed.pitch, status::ok};
}

/// The paper's printed forms throughout: psi from Eq. (1)'s quadratic at the reference pulse,
/// the half chord from Eq. (3) with acos, eta_s from Eq. (6)'s quadratic ('+' root, whichever
/// root is the right one), then the sensed nadir as SPEC §6.
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

/// The stable closed forms: bias_model_crossings, then process_head.
template <class T>
head_outcome<T> stable_closed_form_head(const head_sample<T>& s) noexcept {
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  if (!rho.ok()) return head_outcome<T>::failed(rho.state);
  const crossings<T> measured = bias_model_crossings(s.optics, s.eta, s.phi_n, rho.value);
  return outcome_of(s, process_head(s.frame_body, s.optics.gamma, rho.value, measured));
}

/// The scan model on the sphere, then process_head.
template <class T>
head_outcome<T> scan_sphere_head(const head_sample<T>& s) noexcept {
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  if (!rho.ok()) return head_outcome<T>::failed(rho.state);
  const crossings<T> measured = scan_model_crossings_sphere(s.optics, s.eta, s.phi_n, rho.value);
  return outcome_of(s, process_head(s.frame_body, s.optics.gamma, rho.value, measured));
}

/// The scan model on the ellipsoid, processed on the equatorial sphere seen from |p| (SPEC §6's
/// default processing radius).
template <class T>
head_outcome<T> scan_ellipsoid_head(const head_sample<T>& s) noexcept {
  const result<T> rho_p = disk_angular_radius(s.a_eq_m, norm(s.p_eci_m));
  if (!rho_p.ok()) return head_outcome<T>::failed(rho_p.state);
  const crossings<T> measured =
      scan_model_crossings_ellipsoid(s.optics, s.frame_eci, s.p_eci_m, s.a_eq_m, s.b_pol_m);
  return outcome_of(s, process_head(s.frame_body, s.optics.gamma, rho_p.value, measured));
}

template <class T>
head_outcome<T> run_head(method m, const head_sample<T>& s) noexcept {
  switch (m) {
    case method::paper_quadratic:
      return paper_quadratic_head(s);
    case method::stable_closed_form:
      return stable_closed_form_head(s);
    case method::scan_sphere:
      return scan_sphere_head(s);
    case method::scan_ellipsoid:
      return scan_ellipsoid_head(s);
  }
  return head_outcome<T>::failed(status::invalid);
}

}  // namespace conescan::accuracy
