// A safeguarded Newton iteration on a bracket, shared by the crossing solvers.
#pragma once

#include <limits>

#include "conescan/scalar.hpp"

namespace conescan {

/// A function value and its derivative.
template <class T>
struct value_slope {
  T value;
  T slope;
};

template <class T>
struct root {
  T x;
  int iterations;
};

/// Iteration cap of bracketed_newton: enough bisections to shrink a 2 pi bracket to one ulp of
/// T, twice over (every Newton step that fails to halve the bracket is followed by a bisection).
template <class T>
int bracketed_newton_max_iterations() noexcept {
  return 2 * std::numeric_limits<T>::digits + 16;
}

/// Root of f in [lo, hi], given f(lo) and f(hi) of opposite signs (the caller checks), from the
/// first guess x0. Newton steps are taken while they stay inside the bracket and at least halve
/// the previous step; otherwise the bracket is bisected (Numerical Recipes' rtsafe), so it never
/// diverges. Stops when the Newton correction or the bracket is below 4 ulp of max(1, |x|), f is
/// exactly 0, or after
/// bracketed_newton_max_iterations() steps. Returns the root and the steps taken.
/// Accuracy: |x - root| <= ~4 ulp + |f rounding error| / |f'|.
template <class T, class F>
root<T> bracketed_newton(const F& f, T lo, T hi, T x0) noexcept {
  using std::abs;
  value_slope<T> f_lo = f(lo);
  if (f_lo.value == T(0)) return {lo, 0};
  // Orient the bracket so that f(lo) < 0 < f(hi).
  if (f_lo.value > T(0)) {
    T swap = lo;
    lo = hi;
    hi = swap;
  }
  if (!(x0 > (lo < hi ? lo : hi) && x0 < (lo < hi ? hi : lo))) x0 = (lo + hi) / T(2);
  T x = x0;
  T step_before = abs(hi - lo);
  T step = step_before;
  const T eps = std::numeric_limits<T>::epsilon();
  const int max_iterations = bracketed_newton_max_iterations<T>();
  int i = 0;
  for (; i < max_iterations; ++i) {
    value_slope<T> fx = f(x);
    if (fx.value == T(0)) return {x, i + 1};
    if (fx.value < T(0))
      lo = x;
    else
      hi = x;
    T newton = x - fx.value / fx.slope;
    T proposed = abs(fx.value / fx.slope);
    T scale = abs(x) > T(1) ? abs(x) : T(1);
    // Converged: the Newton correction is below rounding. Tested before the bracket, because at
    // the root the correction may land exactly on the bracket end just set to x.
    if (proposed <= T(4) * eps * scale) return {newton, i + 1};
    bool inside = is_finite(newton) && (newton - lo) * (newton - hi) < T(0);
    if (inside && T(2) * proposed <= step_before) {
      step_before = step;
      step = abs(newton - x);
      x = newton;
    } else {
      step_before = step;
      T mid = (lo + hi) / T(2);
      step = abs(mid - x);
      x = mid;
    }
    if (abs(hi - lo) <= T(4) * eps * scale) return {x, i + 1};
  }
  return {x, i};
}

/// A largest value found by golden_section_maximum, and its place.
template <class T>
struct golden_maximum {
  T x;
  T value;
};

/// Golden-section search for the largest value of f (a T) on [lo, hi], f unimodal there: at most
/// `steps` shrinkings of the bracket by 0.618 (each one evaluation of f), fewer where stop(lo, hi)
/// says the bracket is small enough. Returns the better of the last two interior points. The one
/// search of the library: the disk centre's rare paths (scan_model_iterative.hpp), the pulse's
/// peak and the slope locator's extremum (sensor_physics/).
template <class T, class F, class Stop>
golden_maximum<T> golden_section_maximum(const F& f, T lo, T hi, int steps,
                                         const Stop& stop) noexcept {
  using std::sqrt;
  const T ratio = (sqrt(T(5)) - T(1)) / T(2);
  T x1 = hi - ratio * (hi - lo);
  T x2 = lo + ratio * (hi - lo);
  T f1 = f(x1);
  T f2 = f(x2);
  for (int i = 0; i < steps && !stop(lo, hi); ++i) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = f(x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = f(x1);
    }
  }
  return f1 > f2 ? golden_maximum<T>{x1, f1} : golden_maximum<T>{x2, f2};
}

/// golden_section_maximum over all `steps`.
template <class T, class F>
golden_maximum<T> golden_section_maximum(const F& f, T lo, T hi, int steps) noexcept {
  return golden_section_maximum(f, lo, hi, steps, [](const T&, const T&) { return false; });
}

}  // namespace conescan
