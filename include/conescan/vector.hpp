// Small 3-vector geometry on glm::vec<3, T>.
//
// GLM's own dot/cross/length/normalize static-assert IEEE float types, so the core keeps these
// generic versions; GLM provides the storage and the element-wise arithmetic.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>

namespace conescan {

template <class T>
using vec3 = glm::vec<3, T, glm::defaultp>;

template <class T>
T dot(const vec3<T>& a, const vec3<T>& b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class T>
vec3<T> cross(const vec3<T>& a, const vec3<T>& b) noexcept {
  return vec3<T>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

template <class T>
T norm(const vec3<T>& a) noexcept {
  using std::sqrt;
  return sqrt(dot(a, a));
}

/// a / |a|. A zero vector gives NaN components: callers guard degenerate geometry by status.
template <class T>
vec3<T> unit(const vec3<T>& a) noexcept {
  T n = norm(a);
  return vec3<T>(a.x / n, a.y / n, a.z / n);
}

template <class T>
vec3<T> scaled(const vec3<T>& a, const T& s) noexcept {
  return vec3<T>(a.x * s, a.y * s, a.z * s);
}

/// Angle between two vectors of any length, by atan2(|a x b|, a.b): accurate near 0 and pi,
/// where acos of the normalised dot product loses half the digits.
template <class T>
T angle_between(const vec3<T>& a, const vec3<T>& b) noexcept {
  using std::atan2;
  return atan2(norm(cross(a, b)), dot(a, b));
}

}  // namespace conescan
