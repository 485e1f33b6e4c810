// The misaligned optical axis from the misalignment's components, smooth at sigma = 0.
//
// The estimator carries the misalignment as x = sigma cos phi_A and y = sigma sin phi_A (MODEL
// §4), because at sigma = 0, the usual start of a fit, phi_A is undefined and sigma = hypot(x, y)
// has no derivative. The core builds the axis (and the whole scan circle) from the components
// without that square root (include/conescan/misalignment_components.hpp: Taylor series in
// sigma^2 below misalignment_series_limit); this is its view with named members, in radians.
#pragma once

#include "calibration/forward_model.hpp"
#include "conescan/misalignment_components.hpp"

namespace conescan::calibration {

/// The optical axis A in the scan frame (e1, e2, e3 = S), unit.
template <class T>
struct optical_axis {
  T x;  ///< sin sigma cos phi_A
  T y;  ///< sin sigma sin phi_A
  T z;  ///< cos sigma
};

/// A from the components x = sigma cos phi_A, y = sigma sin phi_A (rad). Domain: sigma < pi
/// (sinc has no zero there); the core refuses sigma >= gamma anyway.
template <class T>
optical_axis<T> optical_axis_from_components(const T& x_rad, const T& y_rad) {
  const vec3<T> a = conescan::optical_axis_from_components(x_rad, y_rad);
  return {a.x, a.y, a.z};
}

}  // namespace conescan::calibration
