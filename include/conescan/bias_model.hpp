// The paper's forward model: the misalignment as a fixed cone-angle bias (MODEL §5, "bias").
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/half_chord.hpp"

namespace conescan {

/// The bias model's cone angle: psi at the reference-pulse azimuth phi = 0 (Phi_B = -phi_a), held
/// for the whole scan (MODEL §5). It depends on the optics only: compute it once per head.
/// Statuses: those of misaligned_cone_angle.
template <class T>
result<T> bias_cone_angle(const head_optics<T>& optics) noexcept {
  return misaligned_cone_angle(optics.gamma, optics.sigma, T(-optics.phi_a));
}

/// Crossings of the bias model for its cone angle psi_b (bias_cone_angle): both crossings lie
/// symmetrically about the nadir's azimuth phi_n, so the phase error is exactly 0.
///   eta, phi_n: true nadir's angle from S and azimuth about S (rad); rho: Earth disk's angular
///   radius (rad), sphere only.
/// Statuses: those of half_chord (invalid, miss, engulfed, grazing), invalid for a non-finite
/// phi_n. A phi_n beyond +-2 pi is first reduced to (-pi, pi] (the crossings are then about it).
/// Closed form, no iteration; accuracy that of half_chord.
template <class T>
crossings<T> bias_model_crossings(const T& psi_b, const T& eta, const T& phi_n,
                                  const T& rho) noexcept {
  if (!is_finite(phi_n)) return crossings<T>::failed(status::invalid);
  result<T> phi = half_chord(psi_b, eta, rho);
  if (!phi.ok()) return crossings<T>::failed(phi.state);
  // Beyond one turn, phi_n's whole turns would eat the chord's digits (at 1e17 rad nothing of
  // phi_n +- Phi is left: a fuzzing finding), so the centre is taken modulo 2 pi there.
  using std::abs;
  const T centre = abs(phi_n) <= T(2) * pi<T>() ? phi_n : wrap_pi(phi_n);
  return {centre - phi.value, centre + phi.value, status::ok, 0};
}

/// The same from the head's optics: bias_cone_angle, then the crossings above.
template <class T>
crossings<T> bias_model_crossings(const head_optics<T>& optics, const T& eta, const T& phi_n,
                                  const T& rho) noexcept {
  result<T> psi = bias_cone_angle(optics);
  if (!psi.ok()) return crossings<T>::failed(psi.state);
  return bias_model_crossings(psi.value, eta, phi_n, rho);
}

}  // namespace conescan
