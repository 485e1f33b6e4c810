// The floor: the least work a closed-form head sample can do. Only the transcendental calls
// that the bias model and the inversion need, each evaluated once, joined by algebra; no domain
// checks, no statuses, no cancellation-avoiding rewrites, no root choice. Each method's cost is
// quoted as a ratio to it (docs/PERFORMANCE.md). Valid only where the head is ok (it returns
// NaN or garbage elsewhere), which is where it is timed.
#pragma once

#include "accuracy/head_sample.hpp"

namespace conescan::accuracy {

/// Returns roll + pitch + eta_err so that no part of the work is dead code.
/// Calls: cos gamma, sin gamma, sin sigma, cos sigma, cos phi_a, cos eta, sin eta, cos phi_n,
/// sin phi_n, acos (eta_s), atan2 twice (roll, pitch), and square roots.
template <class T>
T floor_kernel(const head_sample<T>& s) noexcept {
  using std::acos;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T cos_gamma = cos(s.optics.gamma), sin_gamma = sin(s.optics.gamma);
  // psi at the reference pulse, Eq. (1) as a quadratic in cos psi.
  const T h = sin(s.optics.sigma) * cos(s.optics.phi_a);
  const T cos_sigma = cos(s.optics.sigma);
  const T r2 = cos_sigma * cos_sigma + h * h;
  const T cos_psi = (cos_sigma * cos_gamma - h * sqrt(r2 - cos_gamma * cos_gamma)) / r2;
  const T sin_psi = sqrt(T(1) - cos_psi * cos_psi);
  // rho from sin rho = R / r.
  const T sin_rho = s.radius_m / s.r_m;
  const T cos_rho = sqrt(T(1) - sin_rho * sin_rho);
  // cos of the half chord, Eq. (3): no acos needed, the inversion only uses its cosine.
  const T cos_half_chord = (cos_rho - cos_psi * cos(s.eta)) / (sin_psi * sin(s.eta));
  // eta_s, Eq. (6) as a quadratic ('+' root).
  const T k = sin_gamma * cos_half_chord;
  const T q2 = cos_gamma * cos_gamma + k * k;
  const T cos_eta_s = (cos_gamma * cos_rho - k * sqrt(q2 - cos_rho * cos_rho)) / q2;
  const T sin_eta_s = sqrt(T(1) - cos_eta_s * cos_eta_s);
  // Sensed nadir at the phase phi_n (the bias model's crossings are symmetric about it).
  const T radial_1 = sin_eta_s * cos(s.phi_n), radial_2 = sin_eta_s * sin(s.phi_n);
  const vec3<T>& e1 = s.frame_body.e1;
  const vec3<T>& e2 = s.frame_body.e2;
  const vec3<T>& e3 = s.frame_body.e3;
  const T n_x = cos_eta_s * e3.x + radial_1 * e1.x + radial_2 * e2.x;
  const T n_y = cos_eta_s * e3.y + radial_1 * e1.y + radial_2 * e2.y;
  const T n_z = cos_eta_s * e3.z + radial_1 * e1.z + radial_2 * e2.z;
  const T roll = atan2(n_y, n_z);
  const T pitch = atan2(-n_x, sqrt(n_y * n_y + n_z * n_z));
  return roll + pitch + (acos(cos_eta_s) - s.eta);
}

}  // namespace conescan::accuracy
