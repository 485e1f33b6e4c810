// How strongly the chord inversion amplifies an error in the measured half chord, at a head
// sample: |d eta / d Phi| of MODEL §6 (chord_inversion_amplification) at the half chord that the
// bias model measures on the sphere, and at the root nearest eta0 that the processing picks. The
// error of every method grows with it (docs/ACCURACY.md). NaN where the cone does not cross the
// disk; infinite where the chord has no real root (beyond the fold).
#pragma once

#include "accuracy/head_sample.hpp"
#include "conescan/cone_angle.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/nadir_angle.hpp"

namespace conescan::accuracy {

template <class T>
struct chord_conditioning {
  T half_chord;     ///< rad, NaN without a crossing
  T amplification;  ///< |d eta / d Phi| at the true eta, NaN without a crossing
};

template <class T>
chord_conditioning<T> aligned_chord_conditioning(const head_sample<T>& s) noexcept {
  const T nan = not_a_number<T>();
  const result<T> rho = disk_angular_radius(s.radius_m, s.r_m);
  if (!rho.ok()) return {nan, nan};
  // half_chord() refuses grazing chords; the conditioning is wanted there too, so the
  // half-angle form is repeated without that refusal.
  using std::atan2;
  using std::sin;
  using std::sqrt;
  const result<T> misaligned =
      misaligned_cone_angle(s.optics.gamma, s.optics.sigma, T(-s.optics.phi_a));
  if (!misaligned.ok()) return {nan, nan};
  const T& psi = misaligned.value;
  const T p1 = sin((rho.value + psi - s.eta) / T(2)) * sin((rho.value - psi + s.eta) / T(2));
  const T p2 = sin((psi + s.eta + rho.value) / T(2)) * sin((psi + s.eta - rho.value) / T(2));
  if (!(p1 > T(0)) || !(p2 > T(0))) return {nan, nan};
  const T phi = T(2) * atan2(sqrt(p1), sqrt(p2));
  const nadir_angle_roots<T> roots = nadir_angle_roots_from_chord(s.optics.gamma, rho.value, phi);
  if (roots.state != status::ok) return {phi, std::numeric_limits<T>::infinity()};
  using std::abs;
  const T eta0 = angle_between(s.frame_body.e3, vec3<T>(T(0), T(0), T(1)));
  const T eta_s = abs(roots.plus - eta0) <= abs(roots.minus - eta0) ? roots.plus : roots.minus;
  return {phi, chord_inversion_amplification(eta_s, roots)};
}

}  // namespace conescan::accuracy
