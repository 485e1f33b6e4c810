// A test scalar whose math is reachable only by argument-dependent lookup (STYLE.md practice 2).
//
// conescan_test::adl_real wraps a long double. Its sin, cos, sqrt, ... are free functions of
// namespace conescan_test and nothing else: a core header that writes std::sin(x) instead of
// `using std::sin; sin(x)` does not compile for it. It is also built to reject the other habits
// that break non-IEEE scalars (Boost.Multiprecision and the like):
//  - construction from float, double and long double is deleted, so a double literal in the core
//    (`x * 0.5`, `T(3.14159)`) is a compile error; integers convert implicitly, as they are exact;
//  - the only way out is an explicit conversion to long double, so nothing silently degrades to
//    double arithmetic;
//  - std::numeric_limits<adl_real>::is_iec559 is false, so GLM's dot/cross/length/normalize
//    (which static-assert IEEE types) cannot be used on it.
#pragma once

#include <cmath>
#include <limits>
#include <ostream>
#include <type_traits>

#include "conescan/scalar.hpp"

namespace conescan_test {

class adl_real {
 public:
  constexpr adl_real() noexcept : value_(0) {}

  /// Integers are exact in any scalar, so the core may build constants from them (T(2), x * 2).
  template <class I, std::enable_if_t<std::is_integral_v<I>, int> = 0>
  constexpr adl_real(I i) noexcept : value_(static_cast<long double>(i)) {}  // NOLINT implicit

  /// Floating literals would carry double's precision into every scalar type: refused.
  adl_real(float) = delete;
  adl_real(double) = delete;
  adl_real(long double) = delete;

  /// The one deliberate way in from a floating value (tests and numeric_limits only).
  static constexpr adl_real from_long_double(long double v) noexcept { return adl_real(v, tag{}); }

  explicit constexpr operator long double() const noexcept { return value_; }
  constexpr long double get() const noexcept { return value_; }

  constexpr adl_real operator-() const noexcept { return adl_real(-value_, tag{}); }
  constexpr adl_real operator+() const noexcept { return *this; }
  constexpr adl_real& operator+=(const adl_real& o) noexcept {
    value_ += o.value_;
    return *this;
  }
  constexpr adl_real& operator-=(const adl_real& o) noexcept {
    value_ -= o.value_;
    return *this;
  }
  constexpr adl_real& operator*=(const adl_real& o) noexcept {
    value_ *= o.value_;
    return *this;
  }
  constexpr adl_real& operator/=(const adl_real& o) noexcept {
    value_ /= o.value_;
    return *this;
  }

  // Hidden friends: found by ADL only, and integers convert on either side (x < 0, 2 * x).
  friend constexpr adl_real operator+(adl_real a, const adl_real& b) noexcept { return a += b; }
  friend constexpr adl_real operator-(adl_real a, const adl_real& b) noexcept { return a -= b; }
  friend constexpr adl_real operator*(adl_real a, const adl_real& b) noexcept { return a *= b; }
  friend constexpr adl_real operator/(adl_real a, const adl_real& b) noexcept { return a /= b; }
  friend constexpr bool operator==(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ == b.value_;
  }
  friend constexpr bool operator!=(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ != b.value_;
  }
  friend constexpr bool operator<(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ < b.value_;
  }
  friend constexpr bool operator<=(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ <= b.value_;
  }
  friend constexpr bool operator>(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ > b.value_;
  }
  friend constexpr bool operator>=(const adl_real& a, const adl_real& b) noexcept {
    return a.value_ >= b.value_;
  }
  friend std::ostream& operator<<(std::ostream& s, const adl_real& x) { return s << x.value_; }

 private:
  struct tag {};
  constexpr adl_real(long double v, tag) noexcept : value_(v) {}
  long double value_;
};

// The math of adl_real: free functions of its own namespace, reachable only by ADL.
#define CONESCAN_TEST_ADL_UNARY(name)                      \
  inline adl_real name(const adl_real& x) noexcept {       \
    return adl_real::from_long_double(std::name(x.get())); \
  }
#define CONESCAN_TEST_ADL_BINARY(name)                                  \
  inline adl_real name(const adl_real& x, const adl_real& y) noexcept { \
    return adl_real::from_long_double(std::name(x.get(), y.get()));     \
  }
CONESCAN_TEST_ADL_UNARY(sin)
CONESCAN_TEST_ADL_UNARY(cos)
CONESCAN_TEST_ADL_UNARY(tan)
CONESCAN_TEST_ADL_UNARY(asin)
CONESCAN_TEST_ADL_UNARY(acos)
CONESCAN_TEST_ADL_UNARY(atan)
CONESCAN_TEST_ADL_UNARY(sqrt)
CONESCAN_TEST_ADL_UNARY(abs)
CONESCAN_TEST_ADL_UNARY(fabs)
CONESCAN_TEST_ADL_UNARY(exp)
CONESCAN_TEST_ADL_UNARY(log)
CONESCAN_TEST_ADL_UNARY(floor)
CONESCAN_TEST_ADL_UNARY(ceil)
CONESCAN_TEST_ADL_UNARY(round)
CONESCAN_TEST_ADL_UNARY(trunc)
CONESCAN_TEST_ADL_BINARY(atan2)
CONESCAN_TEST_ADL_BINARY(hypot)
CONESCAN_TEST_ADL_BINARY(fmod)
CONESCAN_TEST_ADL_BINARY(remainder)
CONESCAN_TEST_ADL_BINARY(pow)
CONESCAN_TEST_ADL_BINARY(fmin)
CONESCAN_TEST_ADL_BINARY(fmax)
#undef CONESCAN_TEST_ADL_UNARY
#undef CONESCAN_TEST_ADL_BINARY

inline bool isnan(const adl_real& x) noexcept {
  return std::isnan(x.get());
}
inline bool isfinite(const adl_real& x) noexcept {
  return std::isfinite(x.get());
}
inline bool isinf(const adl_real& x) noexcept {
  return std::isinf(x.get());
}

/// The scalar types every generic property test runs over (STYLE.md practice 9).
#define CONESCAN_TEST_SCALARS float, double, long double, ::conescan_test::adl_real

/// A long double test value (a reference computed in long double, a non-integer input) in T,
/// rounded once. The only sanctioned way to bring a floating value into adl_real.
template <class T>
T scalar_from(long double v) noexcept {
  if constexpr (std::is_same_v<T, adl_real>)
    return adl_real::from_long_double(v);
  else
    return static_cast<T>(v);
}

/// Machine epsilon of T, for tolerances in the scalar's own terms.
template <class T>
T eps() {
  return std::numeric_limits<T>::epsilon();
}

/// The same value, NaN counting as equal to NaN: for "bit for bit the same results" checks of
/// code that may return NaN (a status's numbers).
inline bool same_or_both_nan(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// Degrees given as num / den, converted in T (no floating literal).
template <class T>
T deg(int num, int den = 1) {
  return conescan::deg_to_rad(T(T(num) / T(den)));
}

}  // namespace conescan_test

namespace std {

/// numeric_limits of adl_real: those of long double, except is_iec559, which is false so that
/// GLM's IEEE-only functions refuse it.
template <>
class numeric_limits<conescan_test::adl_real> {
  using base = numeric_limits<long double>;
  using T = conescan_test::adl_real;

 public:
  static constexpr bool is_specialized = true;
  static constexpr T min() noexcept { return T::from_long_double(base::min()); }
  static constexpr T max() noexcept { return T::from_long_double(base::max()); }
  static constexpr T lowest() noexcept { return T::from_long_double(base::lowest()); }
  static constexpr int digits = base::digits;
  static constexpr int digits10 = base::digits10;
  static constexpr int max_digits10 = base::max_digits10;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr int radix = base::radix;
  static constexpr T epsilon() noexcept { return T::from_long_double(base::epsilon()); }
  static constexpr T round_error() noexcept { return T::from_long_double(base::round_error()); }
  static constexpr int min_exponent = base::min_exponent;
  static constexpr int min_exponent10 = base::min_exponent10;
  static constexpr int max_exponent = base::max_exponent;
  static constexpr int max_exponent10 = base::max_exponent10;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr bool has_signaling_NaN = base::has_signaling_NaN;
  static constexpr float_denorm_style has_denorm = base::has_denorm;
  static constexpr bool has_denorm_loss = base::has_denorm_loss;
  static constexpr T infinity() noexcept { return T::from_long_double(base::infinity()); }
  static constexpr T quiet_NaN() noexcept { return T::from_long_double(base::quiet_NaN()); }
  static constexpr T signaling_NaN() noexcept { return T::from_long_double(base::signaling_NaN()); }
  static constexpr T denorm_min() noexcept { return T::from_long_double(base::denorm_min()); }
  static constexpr bool is_iec559 = false;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr bool traps = base::traps;
  static constexpr bool tinyness_before = base::tinyness_before;
  static constexpr float_round_style round_style = base::round_style;
};

}  // namespace std
