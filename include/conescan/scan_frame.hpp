// A sensor head's scan frame and the directions measured in it (MODEL §4).
#pragma once

#include "conescan/status.hpp"
#include "conescan/vector.hpp"

namespace conescan {

/// Orthonormal scan frame of one head, in body axes. The scan azimuth phi is measured about e3
/// from e1, right-handed; the reference pulse fires at phi = 0.
template <class T>
struct scan_frame {
  vec3<T> e1;    ///< unit projection of body +z (nominal nadir) on the plane normal to S
  vec3<T> e2;    ///< e3 x e1
  vec3<T> e3;    ///< spin axis S
  status state;  ///< ok, or invalid for |alpha| >= pi/2 or non-finite angles
};

/// Scan frame from the mounting: alpha = elevation of S from the roll-pitch plane towards nadir,
/// beta = azimuth of its projection from +x towards +y (rad; MODEL §4).
///   S = (cos a cos b, cos a sin b, sin a), e1 = (-sin a cos b, -sin a sin b, cos a),
///   e2 = (sin b, -cos b, 0): the closed forms of the projection and the cross product, exact
/// to rounding and defined for every |alpha| < pi/2. |alpha| >= pi/2 is invalid: body +z then
/// lies on S and the scan reference is undefined.
template <class T>
scan_frame<T> scan_frame_from_mounting(const T& alpha, const T& beta) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  const T nan = not_a_number<T>();
  if (!is_finite(alpha) || !is_finite(beta) || !(abs(alpha) < pi<T>() / T(2)))
    return {vec3<T>(nan), vec3<T>(nan), vec3<T>(nan), status::invalid};
  T ca = cos(alpha), sa = sin(alpha), cb = cos(beta), sb = sin(beta);
  return {vec3<T>(-sa * cb, -sa * sb, ca), vec3<T>(sb, -cb, T(0)), vec3<T>(ca * cb, ca * sb, sa),
          status::ok};
}

/// The unit vector at angle psi from e3 and scan azimuth phi (MODEL §4's line of sight, and
/// MODEL §6's sensed nadir with psi = eta_s, phi = phase): cos psi e3 + sin psi (cos phi e1 +
/// sin phi e2). The frame's axes may be expressed in any common frame (body or ECI).
template <class T>
vec3<T> direction_in_scan_frame(const scan_frame<T>& f, const T& psi, const T& phi) noexcept {
  using std::cos;
  using std::sin;
  T s = sin(psi);
  return scaled(f.e3, cos(psi)) + scaled(f.e1, s * cos(phi)) + scaled(f.e2, s * sin(phi));
}

/// A direction's polar angle from e3 and azimuth about it, in the scan frame.
template <class T>
struct scan_angles {
  T polar;    ///< angle from e3, [0, pi] rad (eta for the nadir)
  T azimuth;  ///< about e3 from e1, [-pi, pi] rad (atan2: -pi when the e2 part is -0; phi_n)
};

/// Polar angle and azimuth of any non-zero vector v (same axes as the frame).
template <class T>
scan_angles<T> scan_angles_of(const scan_frame<T>& f, const vec3<T>& v) noexcept {
  using std::atan2;
  return {angle_between(f.e3, v), atan2(dot(v, f.e2), dot(v, f.e1))};
}

}  // namespace conescan
