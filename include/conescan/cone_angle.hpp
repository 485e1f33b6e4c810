// The misaligned cone angle psi: the angle between the spin axis S and the true line of sight at
// one scan azimuth, when the optical axis A is tilted sigma from S (MODEL §4; paper Eqs. (1), (2)).
#pragma once

#include "conescan/status.hpp"

namespace conescan {

/// Domain of a sensor head's cone: gamma in (0, pi/2), sigma in [0, gamma).
/// sigma >= gamma is refused: the cone about A then no longer encloses S, and for some scan
/// azimuths no line of sight exists (a decision of this project; MODEL §7 names only sigma < 0).
template <class T>
bool cone_in_domain(const T& gamma, const T& sigma) noexcept {
  return is_finite(gamma) && is_finite(sigma) && gamma > T(0) && gamma < pi<T>() / T(2) &&
         sigma >= T(0) && sigma < gamma;
}

/// psi for the scan-azimuth offset phi_b = phi - phi_a (MODEL §4, corrected Eq. (1), stable form):
///   psi = atan2(h, cos sigma) + acos(cos gamma / hypot(cos sigma, h)),  h = sin sigma cos phi_b.
/// It solves cos gamma = cos sigma cos psi + h sin psi (the spherical triangle SAH), taking the
/// root that is gamma when sigma = 0.
/// Domain: cone_in_domain(gamma, sigma), finite phi_b; otherwise status invalid.
/// The acos is evaluated as atan2(sqrt(R^2 - cos^2 gamma), cos gamma), R = hypot(cos sigma, h),
/// with R^2 - cos^2 gamma = (sin gamma - sin sigma sin phi_b)(sin gamma + sin sigma sin phi_b):
/// acos of an argument near 1 (small gamma) loses digits (~500 ulp of psi at gamma = 1 deg), the
/// factored radicand's cancelling factor (sigma -> gamma at phi_b = +-90 deg) is rebuilt from
/// exact differences where it has cancelled. sigma = 0 returns gamma exactly (A = S: the
/// nominal cone).
/// Accuracy: 4 eps (gamma + sigma) absolute (tests/core/test_cone_angle.cpp).
template <class T>
result<T> misaligned_cone_angle(const T& gamma, const T& sigma, const T& phi_b) noexcept {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!cone_in_domain(gamma, sigma) || !is_finite(phi_b)) return result<T>::bad(status::invalid);
  if (sigma == T(0)) return result<T>::good(gamma);
  T sin_sigma = sin(sigma), sin_gamma = sin(gamma);
  T cos_phi_b = cos(phi_b), abs_sin_phi_b = abs(sin(phi_b));
  T h = sin_sigma * cos_phi_b;
  T abs_s_perp = sin_sigma * abs_sin_phi_b;
  // The factor sin gamma - |s_perp| cancels as sigma -> gamma near phi_b = +-90 deg (in float,
  // gamma and sigma within 4e-7 of 90 deg gave psi = -0.10 for 1.296: a fuzzing finding). Where
  // it has lost over 4 bits it is rebuilt from terms without cancellation:
  //   sin gamma - sin sigma = (cos sigma - cos gamma)(cos sigma + cos gamma) / (sin gamma + sin
  //   sigma), cos sigma - cos gamma = 2 sin((gamma + sigma)/2) sin((gamma - sigma)/2)
  // (not 2 cos((gamma + sigma)/2) ...: that cosine loses its digits near 90 deg), and
  //   1 - |sin phi_b| = cos^2 phi_b / (1 + |sin phi_b|).
  T near_factor = sin_gamma - abs_s_perp;
  if (near_factor < sin_gamma / T(16)) {
    T cos_sigma = cos(sigma), cos_gamma = cos(gamma);
    near_factor = T(2) * sin((gamma + sigma) / T(2)) * sin((gamma - sigma) / T(2)) *
                      (cos_sigma + cos_gamma) / (sin_gamma + sin_sigma) +
                  sin_sigma * (cos_phi_b * cos_phi_b) / (T(1) + abs_sin_phi_b);
  }
  // Each factor under its own root: their product underflows for gamma below ~1e-154 rad in
  // double (1e-19 in float), where psi would collapse to h (a fuzzing finding).
  T spread = atan2(sqrt(near_factor) * sqrt(sin_gamma + abs_s_perp), cos(gamma));
  T psi = atan2(h, cos(sigma)) + spread;
  return result<T>::good(psi);
}

/// The same psi from the paper's quadratic form, with the square root that the transcription
/// lost restored (MODEL §4, corrected Eq. (1)):
///   cos psi = [cos sigma cos gamma - h sqrt(cos^2 sigma + h^2 - cos^2 gamma)] / (cos^2 sigma +
///   h^2)
/// Kept to measure it against the stable form: psi = acos(.) loses digits as psi -> 0, and the
/// radicand cancels as sigma -> gamma. Domain and statuses as misaligned_cone_angle, and
/// `invalid` where cos psi rounds to 1 (psi below about sqrt(2 epsilon), 2e-8 rad in double):
/// there acos has no digit of psi left and would return 0, outside [gamma - sigma, gamma +
/// sigma] (a denormal gamma gave psi = 0 with status ok).
template <class T>
result<T> misaligned_cone_angle_quadratic(const T& gamma, const T& sigma, const T& phi_b) noexcept {
  using std::acos;
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!cone_in_domain(gamma, sigma) || !is_finite(phi_b)) return result<T>::bad(status::invalid);
  T h = sin(sigma) * cos(phi_b);
  T cos_sigma = cos(sigma);
  T cos_gamma = cos(gamma);
  T r2 = cos_sigma * cos_sigma + h * h;
  T radicand = r2 - cos_gamma * cos_gamma;
  if (radicand < T(0)) radicand = T(0);  // only by rounding: the domain keeps it positive
  T cos_psi = (cos_sigma * cos_gamma - h * sqrt(radicand)) / r2;
  if (!(cos_psi < T(1))) return result<T>::bad(status::invalid);
  return result<T>::good(acos(cos_psi));
}

/// d psi / d phi at scan azimuth offset phi_b, given psi = misaligned_cone_angle(...) there.
/// From differentiating cos sigma cos psi + sin sigma sin psi cos phi_b = cos gamma:
///   psi' = sin sigma sin psi sin phi_b / (sin sigma cos psi cos phi_b - cos sigma sin psi).
/// The denominator is -hypot(cos sigma, h) sin(acos(cos gamma / hypot)) < 0 on the domain.
template <class T>
T misaligned_cone_angle_slope(const T& sigma, const T& phi_b, const T& psi) noexcept {
  using std::cos;
  using std::sin;
  T s_sigma = sin(sigma);
  return s_sigma * sin(psi) * sin(phi_b) /
         (s_sigma * cos(psi) * cos(phi_b) - cos(sigma) * sin(psi));
}

}  // namespace conescan
