// Angular radius of a spherical Earth seen from the satellite (MODEL §3).
#pragma once

#include "conescan/status.hpp"

namespace conescan {

/// rho with sin rho = radius / r: the angular radius of a sphere of `radius` (the Earth plus the
/// horizon height) seen from orbit radius r (same length unit). Domain: 0 < radius < r, finite;
/// otherwise invalid (the satellite is inside the sphere), and invalid when radius / r underflows
/// to 0 (no disk to see). Accuracy: one asin, a few ulp.
template <class T>
result<T> disk_angular_radius(const T& radius, const T& r) noexcept {
  using std::asin;
  if (!is_finite(radius) || !is_finite(r) || !(radius > T(0)) || !(radius < r))
    return result<T>::bad(status::invalid);
  T ratio = radius / r;
  if (!(ratio > T(0))) return result<T>::bad(status::invalid);
  return result<T>::good(asin(ratio));
}

/// The Earth disk by the sine and cosine of its angular radius rho, which is what the closed
/// forms need (no asin, and no sin(asin(x)) that would round twice).
template <class T>
struct disk_trig {
  T sin_rho;
  T cos_rho;
  status state;  ///< ok, or invalid (as disk_angular_radius)
};

/// sin rho = radius / r and cos rho = sqrt((r - radius)(r + radius)) / r (no cancellation as
/// rho -> 90 deg). Domain and statuses those of disk_angular_radius.
template <class T>
disk_trig<T> disk_trig_of(const T& radius, const T& r) noexcept {
  using std::sqrt;
  const T nan = not_a_number<T>();
  if (!is_finite(radius) || !is_finite(r) || !(radius > T(0)) || !(radius < r))
    return {nan, nan, status::invalid};
  const T ratio = radius / r;
  if (!(ratio > T(0))) return {nan, nan, status::invalid};
  return {ratio, T(sqrt((r - radius) * (r + radius)) / r), status::ok};
}

/// The same from rho itself (rad): ok for rho in (0, pi/2], else invalid.
template <class T>
disk_trig<T> disk_trig_of_angle(const T& rho) noexcept {
  using std::cos;
  using std::sin;
  const T nan = not_a_number<T>();
  if (!is_finite(rho) || !(rho > T(0)) || !(rho <= pi<T>() / T(2)))
    return {nan, nan, status::invalid};
  return {sin(rho), cos(rho), status::ok};
}

}  // namespace conescan
