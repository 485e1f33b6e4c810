// True attitude and roll/pitch of a nadir vector (MODEL §2).
#pragma once

#include <glm/mat3x3.hpp>

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

}  // namespace conescan
