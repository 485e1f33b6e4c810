// Scalar-generic helpers shared by every core header.
//
// The core is templated on the scalar T (float, double, long double, Boost.Multiprecision, or any
// type whose math functions are found by argument-dependent lookup). Rules that follow from that:
// math is called as `using std::sin; sin(x)`, constants are built in T from exact integers, and
// no scalar intermediate is declared `auto` (multiprecision expression templates).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

namespace conescan {

/// pi in the working type, from atan2 so that no double literal limits its precision.
template <class T>
T pi() noexcept {
  using std::atan2;
  return atan2(T(0), T(-1));
}

template <class T>
T deg_to_rad(const T& deg) noexcept {
  return deg * (pi<T>() / T(180));
}

template <class T>
T rad_to_deg(const T& rad) noexcept {
  return rad * (T(180) / pi<T>());
}

/// True for a finite value; false for NaN and +-inf. Written with arithmetic only (inf - inf and
/// NaN - NaN are NaN, which compares unequal to 0), so it needs no isfinite overload for T.
template <class T>
bool is_finite(const T& x) noexcept {
  return x - x == T(0);
}

/// A quiet NaN of T, the value every failed result carries beside its status.
template <class T>
T not_a_number() noexcept {
  return std::numeric_limits<T>::quiet_NaN();
}

/// A scalar's value as a long double, for the counts and indices a routine derives from a scalar
/// (a number of panels, a lattice cell), which carry no derivative. Arithmetic types and
/// Boost.Multiprecision convert; a type that does not (ceres::Jet) supplies an overload of this
/// name in its own namespace, found by argument-dependent lookup (the calibration's for Jet:
/// src/calibration/forward_model.hpp), since calls are unqualified.
template <class T>
long double long_double_value(const T& x) noexcept {
  return static_cast<long double>(x);
}

/// True where T is built from a double (ceres::Jet, Boost.Multiprecision: an integer would
/// convert implicitly); false for the arithmetic types and a type with integer constructors only,
/// which take integers as they are.
template <class T>
inline constexpr bool built_from_double =
    !std::is_arithmetic_v<T> && std::is_constructible_v<T, double>;

/// The integer i in T, exact for |i| < 2^53: T(i), through double where T is built from one.
template <class T>
T integer_value(long long i) noexcept {
  if constexpr (built_from_double<T>)
    return T(static_cast<double>(i));
  else
    return T(i);
}

/// The integer i as a factor of T in a product or quotient with a T: the double itself where T
/// is built from one, so that such a T (ceres::Jet: its product with a Jet of the constant spends
/// a vector product on the constant's zero derivatives) is scaled as by a scalar; integer_value's
/// T otherwise. The same result to the bit: a product or quotient with an exact constant, whose
/// derivatives are zero. Exact for |i| < 2^53.
template <class T>
auto integer_factor(long long i) noexcept {
  if constexpr (built_from_double<T>)
    return static_cast<double>(i);
  else
    return integer_value<T>(i);
}

/// x wrapped to (-pi, pi]. Domain: finite x; NaN and inf give NaN.
template <class T>
T wrap_pi(const T& x) noexcept {
  using std::remainder;
  // Already in range (every error angle of a working sensor): remainder would return x exactly,
  // and it is the slowest call of a CLI row (docs/PERFORMANCE.md).
  if (x > -pi<T>() && x <= pi<T>()) return x;
  // One turn out (a mean anomaly along its first orbit): x -+ 2 pi is exact (Sterbenz, for
  // pi <= |x| <= 4 pi) and is what remainder returns, without the call. The result is checked
  // against (-pi, pi] rather than x against 3 pi, which T may round either way.
  if (x > pi<T>() && x < T(4) * pi<T>()) {
    const T y = x - T(2) * pi<T>();
    if (y <= pi<T>()) return y;
  } else if (x < -pi<T>() && x > -T(4) * pi<T>()) {
    const T y = x + T(2) * pi<T>();
    if (y > -pi<T>()) return y;
  }
  T y = remainder(x, T(2) * pi<T>());  // [-pi, pi]
  if (y <= -pi<T>()) y += T(2) * pi<T>();
  return y;
}

/// x wrapped to [0, 2 pi). Domain: finite x; NaN and inf give NaN.
template <class T>
T wrap_two_pi(const T& x) noexcept {
  using std::fmod;
  T y = fmod(x, T(2) * pi<T>());  // (-2 pi, 2 pi)
  if (y < T(0)) y += T(2) * pi<T>();
  if (y >= T(2) * pi<T>()) y -= T(2) * pi<T>();  // y was a tiny negative number
  return y;
}

}  // namespace conescan
