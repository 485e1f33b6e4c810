// An ellipsoid of revolution seen from a satellite outside it: MODEL §5's tangency function g of a
// line of sight, written for any frame (ECI, or a head's scan frame).
#pragma once

#include "conescan/status.hpp"
#include "conescan/vector.hpp"

namespace conescan {

/// The truth surface as the scan models need it: semi-axes a_eq (equatorial) and b_pol (polar),
/// m, oblate or prolate (the inflated WGS84 ellipsoid, or the apparent horizon surface), its
/// polar axis, and the satellite's position from its centre, both in the working frame.
///
/// MODEL §5 scales x, y by 1/a_eq and z by 1/b_pol (z the polar axis) to P and D; with N = I +
/// (a_eq / b_pol - 1) z z^T, P = N p / a_eq and D = N d / a_eq, so for a unit line of sight d
///   a_eq^2 g = (q.d)^2 - H (1 + kappa (z.d)^2),  q = N^2 p / a_eq,  kappa = (a_eq / b_pol)^2 - 1,
///   H = |P|^2 - 1 (> 0 outside),
/// and q.d < 0 means the ellipsoid lies in front of the satellite. Only dot products with p and z
/// enter: the frame is free, and a head can work in its own scan frame.
template <class T>
struct ellipsoid_horizon {
  vec3<T> position;         ///< p / a_eq, 1
  vec3<T> q;                ///< N^2 p / a_eq, 1
  vec3<T> polar;            ///< unit polar axis z
  T kappa;                  ///< (a_eq / b_pol)^2 - 1: 0 for a sphere, > 0 oblate, < 0 prolate
  T height;                 ///< H = |P|^2 - 1, > 0 for a satellite outside
  T inverse_norm_p_scaled;  ///< 1 / |P|: the sine of the angular radius of the sphere of radius
                            ///< |p| / |P| (the ellipsoid's radius along p), the solvers' start
  status state;             ///< ok, or invalid (see ellipsoid_horizon_of)
};

/// The same horizon in scalar U, member by member.
template <class U, class T>
ellipsoid_horizon<U> scalar_cast(const ellipsoid_horizon<T>& e) noexcept {
  return {vec3<U>(e.position),        vec3<U>(e.q), vec3<U>(e.polar), U(e.kappa), U(e.height),
          U(e.inverse_norm_p_scaled), e.state};
}

/// The ellipsoid as seen from p (m, from its centre) with unit polar axis `polar`, both in one
/// frame. invalid unless a_eq, b_pol > 0, all finite, and the satellite outside (H > 0).
template <class T>
ellipsoid_horizon<T> ellipsoid_horizon_of(const vec3<T>& p, const vec3<T>& polar, const T& a_eq,
                                          const T& b_pol) noexcept {
  using std::sqrt;
  const T nan = not_a_number<T>();
  ellipsoid_horizon<T> e{vec3<T>(nan), vec3<T>(nan), polar, nan, nan, nan, status::invalid};
  if (!is_finite(a_eq) || !is_finite(b_pol) || !(a_eq > T(0)) || !(b_pol > T(0)) ||
      !is_finite(p.x) || !is_finite(p.y) || !is_finite(p.z))
    return e;
  // kappa = (a - b)(a + b) / b^2: (a / b)^2 - 1 would lose two digits of WGS84's 0.0067.
  e.kappa = (a_eq - b_pol) * (a_eq + b_pol) / (b_pol * b_pol);
  const T along = dot(p, polar);
  const vec3<T> p_scaled(p.x / a_eq, p.y / a_eq, p.z / a_eq);
  const T along_scaled = along / a_eq;
  e.position = p_scaled;
  // N^2 p / a = p / a + kappa (p.z) z / a.
  e.q = p_scaled + scaled(polar, T(e.kappa * along_scaled));
  // |P|^2 - 1 = |p / a|^2 + kappa (p.z / a)^2 - 1.
  const T norm_p_scaled_squared = dot(p_scaled, p_scaled) + e.kappa * along_scaled * along_scaled;
  e.height = norm_p_scaled_squared - T(1);
  if (!(e.height > T(0)) || !is_finite(e.height)) return e;
  e.inverse_norm_p_scaled = T(1) / sqrt(norm_p_scaled_squared);
  e.state = status::ok;
  return e;
}

/// a_eq^2 g(d) and its derivative for a unit line of sight d and its derivative d_slope along
/// some parameter. Where q.d >= 0 (the ellipsoid behind) only -H |D|^2 a_eq^2 is kept: continuous,
/// negative, and so "off the Earth" (the iterative solver's horizon function).
template <class T>
void ellipsoid_tangency(const ellipsoid_horizon<T>& e, const vec3<T>& d, const vec3<T>& d_slope,
                        T& value, T& slope) noexcept {
  const T along = dot(e.polar, d);
  const T stretch = T(1) + e.kappa * along * along;
  value = -e.height * stretch;
  slope = T(-2) * e.height * e.kappa * along * dot(e.polar, d_slope);
  const T front = dot(e.q, d);
  if (front < T(0)) {
    value += front * front;
    slope += T(2) * front * dot(e.q, d_slope);
  }
}

}  // namespace conescan
