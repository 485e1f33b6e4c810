// What the electronics compute from one scan: chord and phase -> sensed nadir (MODEL §6), and the
// system solution of several heads.
#pragma once

#include "conescan/attitude.hpp"
#include "conescan/crossings.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/nadir_angle.hpp"
#include "conescan/scan_frame.hpp"

namespace conescan {

/// One head's processed measurement.
template <class T>
struct head_estimate {
  T eta_s;        ///< sensed nadir angle of the spin axis, rad
  vec3<T> nadir;  ///< sensed nadir n_s, unit, body axes
  status state;   ///< ok, or the status of the crossings or of the inversion
};

/// Nominal nadir angle eta0 of a head: the angle between its spin axis and body +z (= pi/2 -
/// alpha for the mounting of scan_frame_from_mounting).
template <class T>
T nominal_nadir_angle(const scan_frame<T>& frame_body) noexcept {
  return angle_between(frame_body.e3, vec3<T>(T(0), T(0), T(1)));
}

/// What the inversion needs of a head whose scan frame is frame_body: cos eta0 = e3.z and
/// sin eta0 = |e3 x z| of nominal_nadir_angle, without its atan2; the envelope in rad.
template <class T>
head_inversion<T> head_inversion_of(const scan_frame<T>& frame_body, const T& cos_gamma,
                                    const T& sin_gamma, const T& envelope) noexcept {
  using std::cos;
  using std::sqrt;
  const vec3<T>& s = frame_body.e3;
  return {cos_gamma, sin_gamma, s.z, T(sqrt(s.x * s.x + s.y * s.y)), T(cos(envelope))};
}

/// MODEL §6 for one head from what it holds (no trigonometry of gamma, eta0 or rho_p here): the
/// half chord W/2 of the measured crossings is inverted on the assumed disk
/// (sensed_nadir_angle_from_chord: the root nearest eta0), and the sensed nadir is
/// n_s = cos eta_s e3 + sin eta_s (cos m e1 + sin m e2) with m the measured phase (one sine and
/// cosine: those of eta_s come with it). `frame_body` is the head's scan frame in body axes.
/// Statuses: the crossings' own, invalid for a frame that is not ok, then those of
/// sensed_nadir_angle_from_chord (invalid, fold, grazing, ambiguous).
template <class T>
head_estimate<T> process_head(const scan_frame<T>& frame_body, const head_inversion<T>& head,
                              const disk_trig<T>& assumed, const crossings<T>& measured) noexcept {
  using std::cos;
  using std::sin;
  const T nan = not_a_number<T>();
  if (measured.state != status::ok) return {nan, vec3<T>(nan), measured.state};
  if (frame_body.state != status::ok) return {nan, vec3<T>(nan), status::invalid};
  const sensed_nadir_angle<T> eta_s =
      sensed_nadir_angle_from_chord(head, assumed, measured.half_chord());
  if (eta_s.state != status::ok) return {nan, vec3<T>(nan), eta_s.state};
  const T phase = measured.phase();
  const T radial = eta_s.sin_eta_s;
  return {eta_s.eta_s,
          scaled(frame_body.e3, eta_s.cos_eta_s) + scaled(frame_body.e1, T(radial * cos(phase))) +
              scaled(frame_body.e2, T(radial * sin(phase))),
          status::ok};
}

/// MODEL §6 for one head: the half chord W/2 of the measured crossings is inverted on the assumed
/// Earth of angular radius rho_p (the root nearest eta0), and the sensed nadir is
/// n_s = cos eta_s e3 + sin eta_s (cos m e1 + sin m e2) with m the measured phase.
/// `frame_body` is the head's scan frame in body axes; `gamma` the nominal cone angle (rad);
/// `envelope` the attitude envelope of MODEL §7 (rad, default 10 deg).
/// Statuses: the crossings' own, then invalid (a frame that is not ok, gamma, rho_p or the half
/// chord outside inversion_in_domain, eta0 outside [0, pi], the envelope outside [0, pi/2]),
/// fold, grazing, ambiguous.
template <class T>
head_estimate<T> process_head(const scan_frame<T>& frame_body, const T& gamma, const T& rho_p,
                              const crossings<T>& measured, const T& eta0,
                              const T& envelope = default_attitude_envelope<T>()) noexcept {
  using std::cos;
  using std::sin;
  const T nan = not_a_number<T>();
  if (measured.state != status::ok) return {nan, vec3<T>(nan), measured.state};
  if (!inversion_in_domain(gamma, rho_p, measured.half_chord()) || !is_finite(eta0) ||
      eta0 < T(0) || eta0 > pi<T>() || !attitude_envelope_in_domain(envelope))
    return {nan, vec3<T>(nan), status::invalid};
  return process_head(frame_body, head_inversion_of(gamma, eta0, envelope),
                      disk_trig<T>{sin(rho_p), cos(rho_p), status::ok}, measured);
}

/// The same with eta0 = nominal_nadir_angle(frame_body). A caller processing many scans of one
/// head computes eta0 once and calls the overload above (or builds a sensor_head).
template <class T>
head_estimate<T> process_head(const scan_frame<T>& frame_body, const T& gamma, const T& rho_p,
                              const crossings<T>& measured) noexcept {
  return process_head(frame_body, gamma, rho_p, measured, nominal_nadir_angle(frame_body));
}

/// The system solution (MODEL §6): the normalised mean of the sensed nadirs of the heads whose
/// status is ok. Status ok, or none when no head is ok (nadir NaN), or invalid when the ok
/// heads' nadirs have no mean direction (they cancel, or are not finite: never the case for
/// process_head's unit vectors of nearby directions, but the sum must not be normalised blindly).
/// [first, last) iterates over head_estimate<T>; nothing is allocated.
template <class T, class Iterator>
head_estimate<T> combine_heads(Iterator first, Iterator last) noexcept {
  vec3<T> sum(T(0));
  int used = 0;
  for (; first != last; ++first) {
    if (first->state != status::ok) continue;
    // +=, not sum = sum + ...: GLM deletes vec3's copy assignment for a scalar with non-trivial
    // members (Boost.Multiprecision), its compound assignment works for any T. Same arithmetic.
    sum += first->nadir;
    ++used;
  }
  const T nan = not_a_number<T>();
  if (used == 0) return {nan, vec3<T>(nan), status::none};
  const T length = norm(sum);
  if (!is_finite(length) || !(length > T(0))) return {nan, vec3<T>(nan), status::invalid};
  return {nan, unit(sum), status::ok};
}

}  // namespace conescan
