// True attitude and roll/pitch of a nadir vector (MODEL §2).
#pragma once

#include <glm/mat3x3.hpp>

#include "conescan/status.hpp"
#include "conescan/vector.hpp"

namespace conescan {

template <class T>
using mat3 = glm::mat<3, 3, T, glm::defaultp>;

/// m v for a column-major glm matrix, generic in T (GLM's own product is fine for IEEE types).
template <class T>
vec3<T> apply(const mat3<T>& m, const vec3<T>& v) noexcept {
  return vec3<T>(m[0].x * v.x + m[1].x * v.y + m[2].x * v.z,
                 m[0].y * v.x + m[1].y * v.y + m[2].y * v.z,
                 m[0].z * v.x + m[1].z * v.y + m[2].z * v.z);
}

/// m^T v: the inverse rotation of a direction cosine matrix.
template <class T>
vec3<T> apply_transpose(const mat3<T>& m, const vec3<T>& v) noexcept {
  return vec3<T>(dot(m[0], v), dot(m[1], v), dot(m[2], v));
}

/// Direction cosine matrix body <- orbital of the 3-2-1 Euler sequence (yaw, then pitch, then
/// roll; MODEL §2): C = R1(roll) R2(pitch) R3(yaw). Angles in rad, any finite value.
template <class T>
mat3<T> dcm_body_from_orbit(const T& roll, const T& pitch, const T& yaw) noexcept {
  using std::cos;
  using std::sin;
  T cr = cos(roll), sr = sin(roll), cp = cos(pitch), sp = sin(pitch), cy = cos(yaw), sy = sin(yaw);
  mat3<T> c(T(0));
  // Rows of C, stored column-major: c[col][row].
  // clang-format off
  c[0][0] = cp * cy;                 c[1][0] = cp * sy;                 c[2][0] = -sp;
  c[0][1] = sr * sp * cy - cr * sy;  c[1][1] = sr * sp * sy + cr * cy;  c[2][1] = sr * cp;
  c[0][2] = cr * sp * cy + sr * sy;  c[1][2] = cr * sp * sy - sr * cy;  c[2][2] = cr * cp;
  // clang-format on
  return c;
}

/// The orbital frame's nadir (+z_o) in body axes for the true attitude (MODEL §2):
/// n = (-sin pitch, sin roll cos pitch, cos roll cos pitch). Yaw does not enter.
template <class T>
vec3<T> nadir_in_body(const T& roll, const T& pitch) noexcept {
  using std::cos;
  using std::sin;
  T cp = cos(pitch);
  return vec3<T>(-sin(pitch), sin(roll) * cp, cos(roll) * cp);
}

template <class T>
struct roll_pitch {
  T roll;   ///< rad, (-pi, pi]
  T pitch;  ///< rad, [-pi/2, pi/2]
};

/// Roll and pitch of any nadir estimate n (body axes, any length; MODEL §2):
/// roll = atan2(n_y, n_z), pitch = atan2(-n_x, hypot(n_y, n_z)). Yaw is not observable.
/// Inverse of nadir_in_body for |pitch| < pi/2.
template <class T>
roll_pitch<T> roll_pitch_from_nadir(const vec3<T>& n) noexcept {
  using std::atan2;
  using std::hypot;
  return {atan2(n.y, n.z), atan2(-n.x, hypot(n.y, n.z))};
}

/// Where roll stops meaning anything (MODEL §7, status gimbal): the largest 1/|cos pitch| of a
/// true attitude whose roll and pitch errors are reported. Beyond it, |pitch| > acos(1/30) =
/// 88.09 deg (within 1.91 deg of +-90 deg), the nadir sits so close to the body x axis that a
/// nadir error across it turns roll by 1/cos pitch times as much: 30 times at the boundary, tens
/// of degrees of roll for a millidegree as pitch nears 90 deg.
template <class T>
T gimbal_secant_max() noexcept {
  return T(30);
}

/// The status of a true pitch (rad) for roll and pitch errors (MODEL §7): gimbal when
/// 1/|cos pitch| > gimbal_secant_max() (tested as |cos pitch| gimbal_secant_max() < 1, so
/// that cos pitch = 0 is gimbal without a division), ok otherwise; invalid for a non-finite
/// pitch. The boundary, |pitch| = acos(1/30) = 88.0898 deg, is exact to the rounding of cos
/// near it (a few ulp of 1/30: 1e-15 deg of pitch; tests/apps/test_gimbal.cpp checks both sides).
template <class T>
status classify_true_pitch(const T& pitch) noexcept {
  using std::abs;
  using std::cos;
  if (!is_finite(pitch)) return status::invalid;
  const T cos_pitch = abs(cos(pitch));
  return cos_pitch * gimbal_secant_max<T>() < T(1) ? status::gimbal : status::ok;
}

}  // namespace conescan
