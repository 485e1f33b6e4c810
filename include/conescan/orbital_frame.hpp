// The orbital (LVLH) frame of MODEL §2.
#pragma once

#include "conescan/attitude.hpp"

namespace conescan {

/// Direction cosine matrix ECI <- orbital, columns x_o, y_o, z_o in ECI (MODEL §2):
///   z_o = -r/|r| (geocentric nadir), y_o = -(r x v)/|r x v| (negative orbit normal),
///   x_o = y_o x z_o (along-track; the velocity direction only on a circular orbit).
/// Domain: r and v finite, not parallel; otherwise the columns are NaN (the orbit layer
/// validates orbits so this cannot happen for a bound orbit).
template <class T>
mat3<T> dcm_eci_from_orbit(const vec3<T>& r_eci, const vec3<T>& v_eci) noexcept {
  vec3<T> z = -unit(r_eci);
  vec3<T> y = -unit(cross(r_eci, v_eci));
  vec3<T> x = cross(y, z);
  return mat3<T>(x, y, z);
}

}  // namespace conescan
