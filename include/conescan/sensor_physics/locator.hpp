// Where the electronics place a crossing on the detector's output y(phi) (MODEL §12, "Locator"):
//  - normalised: y passes k times the pulse's peak, k in (0, 1) (default 1/2);
//  - fixed: y passes the threshold T, in units of the plateau L0 = 1;
//  - slope: the extremum of dy/dphi.
// Earth-in is the rising crossing (the first one, scanning from space onto the Earth), Earth-out
// the falling one (the last). A signal that never passes its level is a miss.
//
// The algorithms work on any signal that gives y and dy/dphi at any scan azimuth of a window
// (`Signal::at(phi)` returning lag_point<T>): the sensor physics chain's exact representation
// (sensor_physics.hpp), or a sampled signal under the first-order hold (sampled_lag_signal below,
// used by the brute-force reference and the tests). Samples bracket the crossing; inside a bracket
// the crossing is the root of the signal itself, never a linear interpolation of y: for the
// first-order hold y inside a step is the smooth function lag_within_step, and its root is
// exactly where the held signal crosses (halving the step moves nothing; the exact-integration
// trap of tests/core/test_sensor_physics_lag.cpp).
#pragma once

#include <cmath>
#include <limits>

#include "conescan/root_finding.hpp"
#include "conescan/sensor_physics/detector.hpp"
#include "conescan/status.hpp"

namespace conescan {

enum class locator_kind : unsigned char { normalised, fixed, slope };

/// A locator and its threshold: k in (0, 1) for normalised, T > 0 (units of L0 = 1) for fixed,
/// unused for slope.
template <class T>
struct horizon_locator {
  locator_kind kind;
  T threshold;
};

/// The level a threshold locator looks for: k peak (normalised) or T (fixed); NaN for slope.
template <class T>
T locator_level(const horizon_locator<T>& locator, const T& peak) noexcept {
  switch (locator.kind) {
    case locator_kind::normalised:
      return locator.threshold * peak;
    case locator_kind::fixed:
      return locator.threshold;
    case locator_kind::slope:
      break;
  }
  return not_a_number<T>();
}

/// The crossing of `level` by y inside [lo, hi], given y(lo) and y(hi) on either side of it (the
/// caller's bracket), by bracketed Newton on y - level with y' from the signal. A jump of y inside
/// the bracket (a step edge without lag) is found to the bracket's 4-ulp resolution: the jump is
/// where the signal passes the level.
template <class T, class Signal>
T crossing_in_bracket(const Signal& signal, const T& level, const T& lo, const T& hi) noexcept {
  auto f = [&](const T& phi) {
    const lag_point<T> p = signal.at(phi);
    return value_slope<T>{T(p.value - level), p.slope};
  };
  return bracketed_newton(f, lo, hi, T((lo + hi) / T(2))).x;
}

/// The first rising crossing of `level` (Earth-in) over the samples phi[0] < ... < phi[count-1]:
/// the first step with y(phi[i]) < level <= y(phi[i+1]). miss when none.
template <class T, class Signal>
result<T> first_rising_crossing(const Signal& signal, const T* phi, int count,
                                const T& level) noexcept {
  if (!is_finite(level)) return result<T>::bad(status::invalid);
  T before = signal.at(phi[0]).value;
  for (int i = 0; i + 1 < count; ++i) {
    const T after = signal.at(phi[i + 1]).value;
    if (before < level && after >= level)
      return result<T>::good(crossing_in_bracket(signal, level, phi[i], phi[i + 1]));
    before = after;
  }
  return result<T>::bad(status::miss);
}

/// The last falling crossing of `level` (Earth-out): the last step with y(phi[i]) >= level >
/// y(phi[i+1]). miss when none.
template <class T, class Signal>
result<T> last_falling_crossing(const Signal& signal, const T* phi, int count,
                                const T& level) noexcept {
  if (!is_finite(level)) return result<T>::bad(status::invalid);
  T after = signal.at(phi[count - 1]).value;
  for (int i = count - 2; i >= 0; --i) {
    const T before = signal.at(phi[i]).value;
    if (before >= level && after < level)
      return result<T>::good(crossing_in_bracket(signal, level, phi[i], phi[i + 1]));
    after = before;
  }
  return result<T>::bad(status::miss);
}

/// The place of the largest value of f(phi) for phi in [lo, hi] by golden-section search (f
/// unimodal there), to the bracket's rounding.
template <class T, class F>
T golden_maximum_place(const F& f, T lo, T hi) noexcept {
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  const auto rounded = [&](const T& a, const T& b) {
    const T scale = abs(a) > abs(b) ? abs(a) : abs(b);
    return !(b - a > T(4) * eps * (scale > T(1) ? scale : T(1)));
  };
  const int steps = 2 * std::numeric_limits<T>::digits;  // 0.618^steps < eps^1.3
  return golden_section_maximum(f, lo, hi, steps, rounded).x;
}

/// The extremum of sign * dy/dphi (sign +1: the steepest rise, Earth-in; -1: the steepest fall,
/// Earth-out) over the samples: the largest sampled value, refined by golden-section search
/// between its neighbours. miss when the extremum is not a rise (fall): sign * y' <= 0 everywhere.
template <class T, class Signal>
result<T> steepest_crossing(const Signal& signal, const T* phi, int count, int sign) noexcept {
  int best = -1;
  T best_slope = T(0);
  for (int i = 0; i < count; ++i) {
    const T slope = T(sign) * signal.at(phi[i]).slope;
    if (slope > best_slope) {
      best = i;
      best_slope = slope;
    }
  }
  if (best < 0) return result<T>::bad(status::miss);
  const T lo = phi[best > 0 ? best - 1 : 0];
  const T hi = phi[best + 1 < count ? best + 1 : count - 1];
  auto f = [&](const T& x) { return T(T(sign) * signal.at(x).slope); };
  return result<T>::good(golden_maximum_place(f, lo, hi));
}

/// The largest y over the samples and inside the steps beside the largest sample (where y' = 0),
/// by golden-section search: the pulse's peak for the normalised locator.
template <class T, class Signal>
T sampled_peak(const Signal& signal, const T* phi, int count) noexcept {
  int best = 0;
  T best_value = signal.at(phi[0]).value;
  for (int i = 1; i < count; ++i) {
    const T v = signal.at(phi[i]).value;
    if (v > best_value) {
      best = i;
      best_value = v;
    }
  }
  const T lo = phi[best > 0 ? best - 1 : 0];
  const T hi = phi[best + 1 < count ? best + 1 : count - 1];
  auto f = [&](const T& x) { return signal.at(x).value; };
  const T refined = f(golden_maximum_place(f, lo, hi));
  return refined > best_value ? refined : best_value;
}

/// A signal sampled on a uniform grid phi_k = start + k step (k = 0 .. count-1) with the detector's
/// output y integrated exactly under the first-order hold (lag_step): at(phi) inside a step is
/// lag_within_step, exact for the held (piecewise-linear) signal. s and y are the caller's arrays.
template <class T>
struct sampled_lag_signal {
  const T* s;
  const T* y;
  int count;
  T start;
  T step;
  T lag;

  lag_point<T> at(const T& phi) const noexcept {
    using std::floor;
    T position = (phi - start) / step;
    int k = position < T(0) ? 0 : static_cast<int>(long_double_value(floor(position)));
    if (k > count - 2) k = count - 2;
    const T x = phi - (start + T(k) * step);
    return lag_within_step(y[k], s[k], s[k + 1], step, lag, x);
  }
};

/// Fills y[0..count-1] with the exact first-order-hold lag of s from y[0] = s[0] (the signal is
/// taken as having been s[0] forever before the grid: start the grid >= lag_history(lag) before
/// the pulse).
template <class T>
void integrate_lag(const T* s, T* y, int count, const T& step, const T& lag) noexcept {
  const lag_weights<T> w = lag_weights_of(step, lag);
  y[0] = s[0];
  for (int k = 0; k + 1 < count; ++k) y[k + 1] = lag_step(w, y[k], s[k], s[k + 1]);
}

}  // namespace conescan
