// The inversion of a measured half chord to the nadir angle of the spin axis (what the
// electronics compute). MODEL §6; paper Eqs. (5)-(7), with the square root of Eq. (6) restored.
#pragma once

#include "conescan/earth_disk.hpp"
#include "conescan/half_chord.hpp"

namespace conescan {

/// Largest error amplification |d eta / d Phi| accepted before a chord is called a fold: 30.
/// At 30 a 0.01 deg chord error already moves eta by 0.3 deg, most of a real sensor's budget, so
/// the chord has stopped determining eta. The value is also where double stops keeping 1e-12 deg:
/// the half ulp of Phi alone costs ~6e-15 deg x |d eta / d Phi| in any formula, and the measured
/// worst case below 30 is 7.6e-13 deg against 1.08e-12 deg at 38 (docs/ACCURACY.md).
template <class T>
T fold_amplification_max() noexcept {
  return T(30);
}

/// Both roots of cos rho_p = cos gamma cos eta + sin gamma sin eta cos Phi, and their spread.
template <class T>
struct nadir_angle_roots {
  T plus;               ///< atan2(k, cos gamma) + acos(cos rho_p / hypot(cos gamma, k)), rad
  T minus;              ///< atan2(k, cos gamma) - acos(...), rad (may be negative)
  T half_separation;    ///< acos(...): the roots merge (a fold) as it goes to 0, rad
  T sin_gamma_sin_phi;  ///< s = sin gamma sin Phi
  T root_gap;           ///< sqrt(R^2 - cos^2 rho_p) = R sin(half_separation)
  status state;         ///< ok, invalid (domain), fold (cos rho_p > R: no real root)
};

/// Domain of the inversion: gamma in (0, pi/2), rho_p in (0, pi/2], half_chord in [0, pi].
template <class T>
bool inversion_in_domain(const T& gamma, const T& rho_p, const T& half_chord) noexcept {
  return is_finite(gamma) && is_finite(rho_p) && is_finite(half_chord) && gamma > T(0) &&
         gamma < pi<T>() / T(2) && rho_p > T(0) && rho_p <= pi<T>() / T(2) && half_chord >= T(0) &&
         half_chord <= pi<T>();
}

/// The terms of Eq. (6) for a half chord Phi: k = sin gamma cos Phi, s = sin gamma sin Phi, and
/// R^2 - cos^2 rho_p = (sin rho_p - s)(sin rho_p + s) (R = hypot(cos gamma, k)), negative
/// where the chord has no real root.
template <class T>
struct chord_terms {
  T k;
  T s;
  T gap;
};

template <class T>
chord_terms<T> chord_terms_of(const T& sin_gamma, const T& sin_rho_p,
                              const T& half_chord) noexcept {
  using std::cos;
  using std::sin;
  const T s = sin_gamma * sin(half_chord);
  return {T(sin_gamma * cos(half_chord)), s, T((sin_rho_p - s) * (sin_rho_p + s))};
}

/// The two roots (MODEL §6, corrected Eq. (6), amplitude form): with k = sin gamma cos Phi,
/// cos rho_p = R cos(eta - delta), R = hypot(cos gamma, k), delta = atan2(k, cos gamma), so
/// eta = delta +- acos(cos rho_p / R). Status fold when cos rho_p > R (the roots have merged and
/// left the real line: no spin-axis angle produces this chord on the assumed Earth).
/// The acos is evaluated as atan2(sqrt(R^2 - cos^2 rho_p), cos rho_p), with
/// R^2 - cos^2 rho_p = sin^2 rho_p - sin^2 gamma sin^2 Phi = (sin rho_p - s)(sin rho_p + s),
/// s = sin gamma sin Phi: acos of a ratio near 1 (roots close together, a wide band around the
/// fold) turns a rounding e of the ratio into e / sin(spread) (1e-4 deg in float at a spread of
/// 1 deg, docs/ACCURACY.md); the factored form cancels only as the geometry itself does.
template <class T>
nadir_angle_roots<T> nadir_angle_roots_from_chord(const T& gamma, const T& rho_p,
                                                  const T& half_chord) noexcept {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T nan = not_a_number<T>();
  if (!inversion_in_domain(gamma, rho_p, half_chord))
    return {nan, nan, nan, nan, nan, status::invalid};
  const chord_terms<T> terms = chord_terms_of(T(sin(gamma)), T(sin(rho_p)), half_chord);
  if (terms.gap < T(0)) return {nan, nan, nan, terms.s, nan, status::fold};
  T delta = atan2(terms.k, T(cos(gamma)));
  T root_gap = sqrt(terms.gap);
  T spread = atan2(root_gap, cos(rho_p));
  return {delta + spread, delta - spread, spread, terms.s, root_gap, status::ok};
}

/// |d eta / d Phi| at a root whose sine is sin_eta_s: from differentiating Eq. (5),
///   d eta / d Phi = sin gamma sin eta sin Phi / (R sin(eta - delta)),  |sin(eta - delta)| =
///   sin(half_separation), and R sin(half_separation) = sqrt(R^2 - cos^2 rho_p) = root_gap, so with
///   s = sin gamma sin Phi only sin eta is new. Infinite at the fold (root_gap = 0).
template <class T>
T chord_inversion_amplification(const T& sin_gamma_sin_phi, const T& root_gap,
                                const T& sin_eta_s) noexcept {
  using std::abs;
  if (!(root_gap > T(0))) return std::numeric_limits<T>::infinity();
  return abs(sin_gamma_sin_phi * sin_eta_s) / root_gap;
}

/// The same at a root eta_s of `roots` (one sine).
template <class T>
T chord_inversion_amplification(const T& eta_s, const nadir_angle_roots<T>& roots) noexcept {
  using std::sin;
  return chord_inversion_amplification(roots.sin_gamma_sin_phi, roots.root_gap, T(sin(eta_s)));
}

/// MODEL §7's default attitude envelope (deg): the largest excursion of the true nadir angle from
/// eta0 that a scene declares; both roots within it are `ambiguous`.
inline constexpr int default_attitude_envelope_deg = 10;

/// The default attitude envelope in rad.
template <class T>
T default_attitude_envelope() noexcept {
  return deg_to_rad(T(default_attitude_envelope_deg));
}

/// Whether an attitude envelope (rad) is in its domain [0, pi/2] (the ambiguity test below
/// relies on it, and a larger envelope would call every chord ambiguous).
template <class T>
bool attitude_envelope_in_domain(const T& envelope) noexcept {
  return is_finite(envelope) && envelope >= T(0) && envelope <= pi<T>() / T(2);
}

/// What the inversion needs of a head, by cosines and sines computed once: the nominal cone
/// gamma in (0, pi/2), the nominal nadir angle eta0 of the spin axis in [0, pi], and the
/// attitude envelope in [0, pi/2].
template <class T>
struct head_inversion {
  T cos_gamma;
  T sin_gamma;
  T cos_eta0;
  T sin_eta0;
  T cos_envelope;
};

/// The head_inversion of gamma, eta0 and the envelope (rad).
template <class T>
head_inversion<T> head_inversion_of(const T& gamma, const T& eta0,
                                    const T& envelope = default_attitude_envelope<T>()) noexcept {
  using std::cos;
  using std::sin;
  return {cos(gamma), sin(gamma), cos(eta0), sin(eta0), cos(envelope)};
}

/// The sensed nadir angle with its cosine and sine.
template <class T>
struct sensed_nadir_angle {
  T eta_s;      ///< rad, in (-pi, pi)
  T cos_eta_s;  ///< from the inversion's own terms (no cosine evaluated)
  T sin_eta_s;
  status state;  ///< ok, invalid, grazing, fold
};

/// The sensed nadir angle eta_s of the spin axis: the root of Eq. (6) nearest eta0 (MODEL §6), with
/// one atan2 and no other transcendental call beyond the cosine and sine of the half chord.
/// With the notation of nadir_angle_roots_from_chord (roots delta +- spread, spread in [0, pi/2]
/// since cos rho_p >= 0, delta in (-pi/2, pi/2)):
///  - the nearer root is delta + spread iff delta <= eta0, decided through tangents
///    (k cos eta0 <= cos gamma sin eta0 where cos eta0 > 0; always for eta0 >= pi/2);
///  - its cosine and sine follow from cos delta = cos gamma / R, sin delta = k / R,
///    cos spread = cos rho_p / R, sin spread = root_gap / R:
///      cos eta_s = (cos gamma cos rho_p -+ k root_gap) / R^2,
///      sin eta_s = (k cos rho_p +- cos gamma root_gap) / R^2,
///    and eta_s = atan2(sin, cos) exactly recovers it: both roots lie in (-pi, pi).
///  - ambiguous (MODEL §7) when both roots lie within the envelope E of eta0: the farther one is
///    |delta - eta0| + spread away, and with E <= pi/2 that is <= E iff cos(delta - eta0) >= 0
///    and cos(|delta - eta0| + spread) >= cos E, both from the same terms:
///      R cos(delta - eta0) = cos gamma cos eta0 + k sin eta0,
///      R sin(delta - eta0) = k cos eta0 - cos gamma sin eta0.
///    The electronics cannot then tell which root is the Earth: the nearer may be wrong by
///    degrees (the two heads at gamma 80 deg: roll off by 6 deg with status ok before).
/// Statuses: invalid (disk not ok, half chord outside [0, pi] or not finite), fold (no real root,
/// or an amplification above fold_amplification_max()), grazing (classify_half_chord), in
/// nadir_angle_from_chord's order, then ambiguous. Accuracy: a few ulp times the amplification.
template <class T>
sensed_nadir_angle<T> sensed_nadir_angle_from_chord(const head_inversion<T>& head,
                                                    const disk_trig<T>& assumed,
                                                    const T& half_chord) noexcept {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T nan = not_a_number<T>();
  if (assumed.state != status::ok || !is_finite(half_chord) || !(half_chord >= T(0)) ||
      !(half_chord <= pi<T>()))
    return {nan, nan, nan, status::invalid};
  const chord_terms<T> terms = chord_terms_of(head.sin_gamma, assumed.sin_rho, half_chord);
  if (terms.gap < T(0)) return {nan, nan, nan, status::fold};
  const status chord_state = classify_half_chord(half_chord);
  if (chord_state != status::ok) return {nan, nan, nan, chord_state};
  const T& k = terms.k;
  const T root_gap = sqrt(terms.gap);
  const bool plus = head.cos_eta0 > T(0) ? k * head.cos_eta0 <= head.cos_gamma * head.sin_eta0
                                         : head.sin_eta0 >= T(0);
  const T along = plus ? root_gap : T(-root_gap);
  const T inverse_radius_squared = T(1) / (head.cos_gamma * head.cos_gamma + k * k);
  const T cos_eta_s = (head.cos_gamma * assumed.cos_rho - k * along) * inverse_radius_squared;
  const T sin_eta_s = (k * assumed.cos_rho + head.cos_gamma * along) * inverse_radius_squared;
  if (!(chord_inversion_amplification(terms.s, root_gap, sin_eta_s) <= fold_amplification_max<T>()))
    return {nan, nan, nan, status::fold};
  using std::abs;
  const T cos_offset = head.cos_gamma * head.cos_eta0 + k * head.sin_eta0;  // R cos(delta - eta0)
  const T sin_offset = k * head.cos_eta0 - head.cos_gamma * head.sin_eta0;  // R sin(delta - eta0)
  const T cos_farther = (cos_offset * assumed.cos_rho - abs(sin_offset) * root_gap) *
                        inverse_radius_squared;  // cos(|delta - eta0| + spread)
  if (cos_offset >= T(0) && cos_farther >= head.cos_envelope)
    return {nan, nan, nan, status::ambiguous};
  return {atan2(sin_eta_s, cos_eta_s), cos_eta_s, sin_eta_s, status::ok};
}

/// The sensed nadir angle eta_s of the spin axis: the root nearest the nominal eta0 in [0, pi]
/// (MODEL §6), `envelope` (rad, [0, pi/2]) the attitude envelope of MODEL §7.
/// Statuses: invalid (domain, eta0 outside [0, pi], envelope outside its domain), fold (no real
/// root, or an amplification above fold_amplification_max()), grazing (classify_half_chord),
/// ambiguous (both roots within the envelope of eta0). Accuracy: a few ulp times the
/// amplification.
template <class T>
result<T> nadir_angle_from_chord(const T& gamma, const T& rho_p, const T& half_chord, const T& eta0,
                                 const T& envelope = default_attitude_envelope<T>()) noexcept {
  using std::cos;
  using std::sin;
  if (!inversion_in_domain(gamma, rho_p, half_chord) || !is_finite(eta0) || eta0 < T(0) ||
      eta0 > pi<T>() || !attitude_envelope_in_domain(envelope))
    return result<T>::bad(status::invalid);
  const sensed_nadir_angle<T> eta_s =
      sensed_nadir_angle_from_chord(head_inversion_of(gamma, eta0, envelope),
                                    disk_trig<T>{sin(rho_p), cos(rho_p), status::ok}, half_chord);
  return eta_s.state == status::ok ? result<T>::good(eta_s.eta_s) : result<T>::bad(eta_s.state);
}

/// The '+' root from the paper's printed quadratic form, square root restored (MODEL §6):
///   cos eta_s = [cos gamma cos rho - k sqrt(cos^2 gamma + k^2 - cos^2 rho)] / (cos^2 gamma + k^2).
/// Kept to measure against the amplitude form: acos loses digits near eta_s = 0 and pi, and the
/// radicand cancels near the fold. Statuses: invalid, grazing, fold (negative radicand).
template <class T>
result<T> nadir_angle_from_chord_quadratic(const T& gamma, const T& rho,
                                           const T& half_chord) noexcept {
  using std::acos;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!inversion_in_domain(gamma, rho, half_chord)) return result<T>::bad(status::invalid);
  status chord_state = classify_half_chord(half_chord);
  if (chord_state != status::ok) return result<T>::bad(chord_state);
  T cos_gamma = cos(gamma);
  T cos_rho = cos(rho);
  T k = sin(gamma) * cos(half_chord);
  T r2 = cos_gamma * cos_gamma + k * k;
  T radicand = r2 - cos_rho * cos_rho;
  if (radicand < T(0)) return result<T>::bad(status::fold);
  T cos_eta = (cos_gamma * cos_rho - k * sqrt(radicand)) / r2;
  if (cos_eta > T(1)) cos_eta = T(1);
  if (cos_eta < T(-1)) cos_eta = T(-1);
  return result<T>::good(acos(cos_eta));
}

}  // namespace conescan
