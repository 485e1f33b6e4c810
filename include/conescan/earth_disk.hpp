// Angular radius of a spherical Earth seen from the satellite (SPEC §3).
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

}  // namespace conescan
