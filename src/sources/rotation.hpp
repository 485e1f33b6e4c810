// Unit quaternions for the attitude sources (double): Hamilton's product, scalar first, each
// quaternion standing for the ACTIVE rotation R(q) of vectors, R(q) v = q v q*, so that
// R(q1 q2) = R(q1) R(q2). A direction cosine matrix C_BA (coordinates in A to coordinates in B)
// is then R(q_BA) with q_BA = conj of CCSDS's A-to-B quaternion (aem.hpp states the mapping).
//
// The logarithm and exponential map a rotation to its rotation vector (angle times axis) and
// back: interpolation on the rotation group interpolates rotation vectors relative to a sample
// (aem.cpp), exact for a rotation about a fixed axis by an angle polynomial in time.
#pragma once

#include <algorithm>
#include <cmath>

#include "conescan/attitude.hpp"
#include "conescan/vector.hpp"

namespace conescan::sources {

// The core's vector dot and norm, which this namespace's quaternion overloads would hide.
using conescan::dot;
using conescan::norm;

struct quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};

inline quaternion operator*(const quaternion& a, const quaternion& b) noexcept {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

inline quaternion conjugate(const quaternion& q) noexcept {
  return {q.w, -q.x, -q.y, -q.z};
}

inline double dot(const quaternion& a, const quaternion& b) noexcept {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

/// |q|: sqrt(q . q) where the squares neither overflow nor underflow (every quaternion a file
/// may hold as a rotation), else scaled by the largest component, so that a refusal states the
/// true norm of (1e200, 1e200, 0, 0) or (1e-200, 0, 0, 0) rather than inf or 0.
inline double norm(const quaternion& q) noexcept {
  const double squared = dot(q, q);
  if (squared > 1e-290 && squared < 1e290) return std::sqrt(squared);
  const double largest = std::max({std::abs(q.w), std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  if (!(largest > 0) || !std::isfinite(largest)) return std::sqrt(squared);
  const quaternion unit{q.w / largest, q.x / largest, q.y / largest, q.z / largest};
  return largest * std::sqrt(dot(unit, unit));
}

inline quaternion scaled(const quaternion& q, double s) noexcept {
  return {q.w * s, q.x * s, q.y * s, q.z * s};
}

/// R(q) for a unit q, column-major as the core's mat3 (`c[col][row]`): v' = apply(R, v).
inline mat3<double> rotation_matrix(const quaternion& q) noexcept {
  const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  mat3<double> m(0.0);
  m[0][0] = 1 - 2 * (yy + zz);
  m[1][0] = 2 * (xy - wz);
  m[2][0] = 2 * (xz + wy);
  m[0][1] = 2 * (xy + wz);
  m[1][1] = 1 - 2 * (xx + zz);
  m[2][1] = 2 * (yz - wx);
  m[0][2] = 2 * (xz - wy);
  m[1][2] = 2 * (yz + wx);
  m[2][2] = 1 - 2 * (xx + yy);
  return m;
}

/// The unit quaternion q (w >= 0) with rotation_matrix(q) = m, for a proper orthogonal m
/// (Shepperd's method: from the largest of w, x, y, z, so that no division loses digits; exact to
/// a few ulp of the matrix's elements). The inverse of rotation_matrix.
inline quaternion quaternion_from_rotation_matrix(const mat3<double>& m) noexcept {
  // m[col][row]: r(i, j) is row i, column j.
  const auto r = [&](int i, int j) { return m[j][i]; };
  const double trace = r(0, 0) + r(1, 1) + r(2, 2);
  quaternion q;
  if (trace >= r(0, 0) && trace >= r(1, 1) && trace >= r(2, 2)) {
    const double w4 = 2 * std::sqrt(1 + trace);
    q = {w4 / 4, (r(2, 1) - r(1, 2)) / w4, (r(0, 2) - r(2, 0)) / w4, (r(1, 0) - r(0, 1)) / w4};
  } else if (r(0, 0) >= r(1, 1) && r(0, 0) >= r(2, 2)) {
    const double x4 = 2 * std::sqrt(1 + r(0, 0) - r(1, 1) - r(2, 2));
    q = {(r(2, 1) - r(1, 2)) / x4, x4 / 4, (r(0, 1) + r(1, 0)) / x4, (r(0, 2) + r(2, 0)) / x4};
  } else if (r(1, 1) >= r(2, 2)) {
    const double y4 = 2 * std::sqrt(1 - r(0, 0) + r(1, 1) - r(2, 2));
    q = {(r(0, 2) - r(2, 0)) / y4, (r(0, 1) + r(1, 0)) / y4, y4 / 4, (r(1, 2) + r(2, 1)) / y4};
  } else {
    const double z4 = 2 * std::sqrt(1 - r(0, 0) - r(1, 1) + r(2, 2));
    q = {(r(1, 0) - r(0, 1)) / z4, (r(0, 2) + r(2, 0)) / z4, (r(1, 2) + r(2, 1)) / z4, z4 / 4};
  }
  const double n =
      (q.w < 0 ? -1.0 : 1.0) / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w * n, q.x * n, q.y * n, q.z * n};
}

/// The rotation vector of a unit q: angle in [0, pi] times the unit axis (q and -q give the
/// same). 2 atan2(|v|, |w|) keeps full accuracy at all angles (acos(w) loses half the digits
/// near 0); below |v| = 1e-6 the ratio atan2(s, w) / s is 1 / w to 1e-13 relative.
inline vec3<double> rotation_vector(const quaternion& q) noexcept {
  const double sign = q.w < 0 ? -1.0 : 1.0;
  const double w = sign * q.w;
  const vec3<double> v(sign * q.x, sign * q.y, sign * q.z);
  const double s = norm(v);
  const double factor = s < 1e-6 ? 2.0 / w : 2.0 * std::atan2(s, w) / s;
  return v * factor;
}

/// The unit quaternion of a rotation vector (the inverse of rotation_vector for |phi| <= pi).
inline quaternion quaternion_from_rotation_vector(const vec3<double>& phi) noexcept {
  const double angle = norm(phi);
  const double half = 0.5 * angle;
  // sin(half) / angle, with its series below 1e-4 (error < 1e-18 relative there).
  const double k = angle < 1e-4 ? 0.5 * (1 - half * half / 6) : std::sin(half) / angle;
  return {std::cos(half), phi.x * k, phi.y * k, phi.z * k};
}

/// The angle (rad, [0, pi]) of the rotation from b to a: |rotation_vector(a b*)|.
inline double angle_between(const quaternion& a, const quaternion& b) noexcept {
  return norm(rotation_vector(a * conjugate(b)));
}

}  // namespace conescan::sources
