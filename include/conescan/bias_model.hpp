// The paper's forward model: the misalignment as a fixed cone-angle bias (SPEC §5, "bias").
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/half_chord.hpp"

namespace conescan {

/// Crossings of the bias model: psi is evaluated once, at the reference-pulse azimuth phi = 0
/// (Phi_B = -phi_a), and held for the whole scan, so both crossings lie symmetrically about the
/// nadir's azimuth phi_n and the phase error is exactly 0.
///   eta, phi_n: true nadir's angle from S and azimuth about S (rad); rho: Earth disk's angular
///   radius (rad), sphere only.
/// Statuses: those of misaligned_cone_angle and half_chord (invalid, miss, engulfed, grazing).
/// A phi_n beyond +-2 pi is first reduced to (-pi, pi] (the crossings are then about it).
/// Closed form, no iteration; accuracy that of half_chord.
template <class T>
crossings<T> bias_model_crossings(const head_optics<T>& optics, const T& eta, const T& phi_n,
                                  const T& rho) noexcept {
  result<T> psi = misaligned_cone_angle(optics.gamma, optics.sigma, T(-optics.phi_a));
  if (!psi.ok()) return crossings<T>::failed(psi.state);
  if (!is_finite(phi_n)) return crossings<T>::failed(status::invalid);
  result<T> phi = half_chord(psi.value, eta, rho);
  if (!phi.ok()) return crossings<T>::failed(phi.state);
  // Beyond one turn, phi_n's whole turns would eat the chord's digits (at 1e17 rad nothing of
  // phi_n +- Phi is left: a fuzzing finding), so the centre is taken modulo 2 pi there.
  using std::abs;
  const T centre = abs(phi_n) <= T(2) * pi<T>() ? phi_n : wrap_pi(phi_n);
  return {centre - phi.value, centre + phi.value, status::ok, 0};
}

}  // namespace conescan
