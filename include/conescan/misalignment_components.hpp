// A misaligned head described as a calibration estimates it (MODEL §4, §11): the misalignment by
// its two components x = sigma cos phi_A, y = sigma sin phi_A, and a cone-angle bias dgamma (the
// true half-apex angle is gamma + dgamma), smooth in all three, including at sigma = 0 where
// phi_A is undefined and sigma = hypot(x, y) has no derivative. With ceres::Jet as the scalar the
// derivatives of a predicted chord and phase with respect to (x, y, dgamma) flow through
// scan_model_crossings_sphere / _ellipsoid unchanged (tests/core/test_misalignment_components.cpp
// checks them against finite differences).
//
// Why a second way to build the scan circle: scan_circle_of(head_optics) takes (sigma, phi_A)
// and builds u, v from cos phi_A, sin phi_A, which at sigma = 0 depend on an undefined angle.
// Here u and v are the images of e1 and e2 under the smallest rotation taking S = e3 to the
// optical axis A (Rodrigues' formula about S x A): smooth in A, and equal to e1, e2 at sigma = 0.
#pragma once

#include <limits>

#include "conescan/crossings.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/vector.hpp"

namespace conescan {

/// sigma^2 (rad^2) below which sin(sigma)/sigma and cos(sigma) come from their Taylor series in
/// q = sigma^2 = x^2 + y^2 (through k = 4): eps^(1/4) of T (1.2e-4 in double, sigma < 0.63 deg).
/// There the first term left out, q^5 / 10!, is below eps^(5/4) / 3.6e6, far under an ulp, for
/// every precision; above it sigma = sqrt(q) >= eps^(1/8) (0.011 rad in double), whose derivative
/// 1 / (2 sigma) is finite. Automatic differentiation through sqrt(q) at q = 0 would give 0 x inf.
template <class T>
T misalignment_series_limit() noexcept {
  using std::sqrt;
  return T(sqrt(sqrt(T(std::numeric_limits<T>::epsilon()))));
}

/// cos(sigma) and sin(sigma) / sigma as functions of q = sigma^2, smooth at q = 0.
template <class T>
struct sigma_trig {
  T cos_sigma;
  T sinc_sigma;
};

template <class T>
sigma_trig<T> sigma_trig_of_square(const T& q) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (q < misalignment_series_limit<T>()) {
    // Horner forms of cos = sum (-q)^k / (2k)!, sinc = sum (-q)^k / (2k + 1)!, k = 0..4.
    return {T(T(1) - q / T(2) * (T(1) - q / T(12) * (T(1) - q / T(30) * (T(1) - q / T(56))))),
            T(T(1) - q / T(6) * (T(1) - q / T(20) * (T(1) - q / T(42) * (T(1) - q / T(72)))))};
  }
  const T sigma = sqrt(q);
  return {T(cos(sigma)), T(sin(sigma) / sigma)};
}

/// The optical axis A = (sinc(sigma) x, sinc(sigma) y, cos sigma) in scan-frame components, unit,
/// from the components x = sigma cos phi_A, y = sigma sin phi_A (rad; MODEL §4's A tilted sigma
/// from S towards phi_A). Domain: sigma < pi (sinc has no zero there); finite inputs.
template <class T>
vec3<T> optical_axis_from_components(const T& x_rad, const T& y_rad) noexcept {
  const sigma_trig<T> t = sigma_trig_of_square(T(x_rad * x_rad + y_rad * y_rad));
  return vec3<T>(T(t.sinc_sigma * x_rad), T(t.sinc_sigma * y_rad), t.cos_sigma);
}

/// The scan circle (scan_model.hpp) of a head whose true half-apex angle is gamma_rad (the
/// nominal gamma plus the cone-angle bias) and whose misalignment has the components x, y (rad).
/// The circle's lines of sight, and so every crossing, are those of scan_circle_of({gamma, sigma,
/// phi_A}); only its angle origin differs: u = R e1, v = R e2 = A x u with R the smallest
/// rotation taking S to A (R = I + [w]x + [w]x^2 / (1 + cos sigma), w = S x A), so
///   u = (1 - A_x^2 / (1 + A_z), -A_x A_y / (1 + A_z), -A_x),
///   v = (-A_x A_y / (1 + A_z), 1 - A_y^2 / (1 + A_z), -A_y),
/// and theta = phi at sigma = 0 (rather than phi - phi_A). Statuses: ok, or invalid when
/// gamma_rad is outside (0, pi/2), sigma >= gamma_rad, or an input is not finite (as
/// cone_in_domain). Accuracy: the axis to an ulp (series above); u, v a few ulp.
template <class T>
scan_circle<T> scan_circle_from_components(const T& gamma_rad, const T& x_rad,
                                           const T& y_rad) noexcept {
  using std::cos;
  using std::sin;
  const T q = x_rad * x_rad + y_rad * y_rad;
  if (!is_finite(gamma_rad) || !is_finite(q) || !(gamma_rad > T(0)) ||
      !(gamma_rad < pi<T>() / T(2)) || !(q < gamma_rad * gamma_rad)) {
    const T nan = not_a_number<T>();
    return {vec3<T>(nan), vec3<T>(nan), vec3<T>(nan), nan, nan, nan, status::invalid};
  }
  const vec3<T> a = optical_axis_from_components(x_rad, y_rad);
  const T one_plus_z = T(1) + a.z;
  const T xy = a.x * a.y / one_plus_z;
  const T cos_gamma = cos(gamma_rad), sin_gamma = sin(gamma_rad);
  return {a,
          vec3<T>(T(T(1) - a.x * a.x / one_plus_z), T(-xy), T(-a.x)),
          vec3<T>(T(-xy), T(T(1) - a.y * a.y / one_plus_z), T(-a.y)),
          cos_gamma,
          sin_gamma,
          T(sin_gamma * sin_gamma / (T(1) + cos_gamma)),
          status::ok};
}

/// The scan model (MODEL §5) of such a head: its crossings on a sphere, the unit true nadir in
/// scan-frame components and the disk by sine and cosine of its radius.
template <class T>
crossings<T> component_crossings_sphere(const T& gamma_rad, const T& x_rad, const T& y_rad,
                                        const vec3<T>& nadir_scan,
                                        const disk_trig<T>& disk) noexcept {
  return scan_model_crossings_sphere(scan_circle_from_components(gamma_rad, x_rad, y_rad),
                                     nadir_scan, disk);
}

/// The same on an ellipsoid expressed in the head's scan frame: the closed form of
/// scan_model_crossings_ellipsoid (scan_model_crossings_ellipsoid_newton) without its bracketed
/// fallback, which ceres::Jet cannot run (no fmod) and whose derivatives at sigma = 0 would need
/// phi_A. Where the Newton iteration does not settle (a scan near miss, engulfed or grazing, or
/// a strongly non-spherical surface) the status is `invalid`: the calibration drops such a
/// measurement at the start and refuses a step that leads there. Statuses otherwise those of
/// scan_model_crossings_ellipsoid.
template <class T>
crossings<T> component_crossings_ellipsoid(const T& gamma_rad, const T& x_rad, const T& y_rad,
                                           const ellipsoid_horizon<T>& surface_scan) noexcept {
  const scan_circle<T> circle = scan_circle_from_components(gamma_rad, x_rad, y_rad);
  if (circle.state != status::ok || surface_scan.state != status::ok)
    return crossings<T>::failed(status::invalid);
  return scan_model_crossings_ellipsoid_newton(circle, surface_scan).result;
}

}  // namespace conescan
