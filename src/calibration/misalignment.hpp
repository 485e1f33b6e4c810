// The misaligned optical axis from the misalignment's components, smooth at sigma = 0.
//
// The estimator carries the misalignment as x = sigma cos phi_A and y = sigma sin phi_A (SPEC
// §4), because at sigma = 0, the usual start of a fit, phi_A is undefined and sigma = hypot(x, y)
// has no derivative. The axis A = (sin sigma cos phi_A, sin sigma sin phi_A, cos sigma) in the
// scan frame is smooth in (x, y): A = (sinc(sigma) x, sinc(sigma) y, cos sigma), and sinc and
// cos are functions of q = sigma^2 = x^2 + y^2. Evaluating them through sigma = sqrt(q) would
// give an infinite derivative at q = 0 (automatic differentiation does not know it cancels),
// so below sigma = 0.01 rad they come from their Taylor series in q.
#pragma once

#include <cmath>

#include "calibration/forward_model.hpp"

namespace conescan::calibration {

/// The optical axis A in the scan frame (e1, e2, e3 = S), unit.
template <class T>
struct optical_axis {
  T x;  ///< sin sigma cos phi_A
  T y;  ///< sin sigma sin phi_A
  T z;  ///< cos sigma
};

/// sigma^2 below which the series are used: sigma < 0.01 rad (0.57 deg). There the series to
/// q^4 truncate at q^5 / 10! < 3e-27 (cos) and q^5 / 11! < 3e-28 (sinc), far below an ulp; above
/// it sqrt(q) is at least 0.01 and its derivative finite. Both branches agree to an ulp at the
/// switch (tests/test_calibration_engine.cpp).
inline constexpr double misalignment_series_limit_rad2 = 1e-4;

/// A from the components x = sigma cos phi_A, y = sigma sin phi_A (rad). Domain: sigma < pi
/// (sinc has no zero there); the core refuses sigma >= gamma anyway.
template <class T>
optical_axis<T> optical_axis_from_components(const T& x_rad, const T& y_rad) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T q = x_rad * x_rad + y_rad * y_rad;
  T cos_sigma, sinc_sigma;
  if (value_of(q) < misalignment_series_limit_rad2) {
    // Horner forms of cos = sum (-q)^k / (2k)!, sinc = sum (-q)^k / (2k + 1)!, k = 0..4.
    cos_sigma = 1.0 - q / 2.0 * (1.0 - q / 12.0 * (1.0 - q / 30.0 * (1.0 - q / 56.0)));
    sinc_sigma = 1.0 - q / 6.0 * (1.0 - q / 20.0 * (1.0 - q / 42.0 * (1.0 - q / 72.0)));
  } else {
    const T sigma = sqrt(q);
    cos_sigma = cos(sigma);
    sinc_sigma = sin(sigma) / sigma;
  }
  return {T(sinc_sigma * x_rad), T(sinc_sigma * y_rad), cos_sigma};
}

}  // namespace conescan::calibration
