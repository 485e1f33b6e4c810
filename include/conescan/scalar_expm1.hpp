// e^x - 1 and ln(1 + x) for any scalar: the standard library's (or the scalar's own, found by
// argument-dependent lookup) where it exists, else a form that keeps the digits of a small x.
// The sensor physics needs both where a difference would cancel (the lag's e^{-h/tau} - 1 for
// h << tau, the profile's tail 1 - exp(-v) for v ~ 1e-300); a scalar without them (the ADL test
// type of tests/support/adl_scalar.hpp, which offers only the functions the rest of the core
// uses) gets the fallback.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace conescan {

namespace scalar_detail {
using std::expm1;
using std::log1p;
template <class T, class = void>
struct has_expm1 : std::false_type {};
template <class T>
struct has_expm1<T, std::void_t<decltype(expm1(std::declval<const T&>()))>> : std::true_type {};
template <class T, class = void>
struct has_log1p : std::false_type {};
template <class T>
struct has_log1p<T, std::void_t<decltype(log1p(std::declval<const T&>()))>> : std::true_type {};
}  // namespace scalar_detail

/// e^x - 1: expm1 where T has one; otherwise its Taylor series for |x| < 1/2 (to the scalar's
/// epsilon) and exp(x) - 1 beyond (which cancels less than one digit there).
template <class T>
T expm1_of(const T& x) noexcept {
  if constexpr (scalar_detail::has_expm1<T>::value) {
    using std::expm1;
    return expm1(x);
  } else {
    using std::exp;
    if (!(x < T(1) / T(2) && x > T(-1) / T(2))) return exp(x) - T(1);
    const T eps = std::numeric_limits<T>::epsilon();
    T term = x, sum = T(0);
    for (int k = 2; k < 200; ++k) {
      sum += term;
      term = term * x / T(k);
      if (!(term > eps * (sum < T(0) ? T(-sum) : sum) ||
            -term > eps * (sum < T(0) ? T(-sum) : sum)))
        break;
    }
    return sum + term;
  }
}

/// ln(1 + x): log1p where T has one; otherwise log(u) (u - 1 - ... ) corrected as in Goldberg's
/// trick, log(u) * x / (u - 1) with u = 1 + x rounded, exact to a few ulp.
template <class T>
T log1p_of(const T& x) noexcept {
  if constexpr (scalar_detail::has_log1p<T>::value) {
    using std::log1p;
    return log1p(x);
  } else {
    using std::log;
    const T u = T(1) + x;
    if (u == T(1)) return x;
    return log(u) * x / (u - T(1));
  }
}

}  // namespace conescan
