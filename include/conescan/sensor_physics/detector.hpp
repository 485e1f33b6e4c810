// The detector's first-order lag (MODEL §12, "Detector"): tau y' = s - y in time; with the scan
// azimuth phi = omega t the same ODE reads Lambda dy/dphi = s - y with Lambda = omega tau (rad),
// so every function below works in any one unit of the independent variable (s or rad).
//
// Exact integration over a step of length h of a signal s that is linear on the step (the first-
// order hold): with r = h / Lambda, E = e^{-r}, m = (s1 - s0) / h, the solution
// y(x) = s(x) - m Lambda + (y0 - s0 + m Lambda) e^{-x/Lambda} gives at x = h
//   y1 = s1 - m Lambda + (y0 - s0 + m Lambda) E
//      = E y0 + (1 - E - r phi2) s0 + r phi2 s1,     phi2(r) = (e^{-r} - 1 + r) / r^2,
// whose three weights sum to 1 (a constant signal stays constant) and which for r -> 0 tends to
// the trapezoid rule. The second form is the one evaluated: the first cancels m Lambda against
// itself when h << Lambda (r = 1e-8 left 8 digits). A zero-order hold (s held at s0 over the
// step) delays every crossing by h/2; this update does not
// (tests/core/test_sensor_physics_lag.cpp). For a polynomial signal of any degree the exact update
// generalises to lag_of_polynomial.
#pragma once

#include <cmath>
#include <limits>

#include "conescan/scalar_expm1.hpp"
#include "conescan/status.hpp"

namespace conescan {

/// phi2(r) = (e^{-r} - 1 + r) / r^2 for r >= 0: its Taylor series 1/2 - r/6 + r^2/24 - ...
/// below r = 1/2 (the closed form cancels two digits there and all of them as r -> 0), the
/// closed form above (with expm1). Accuracy: a few ulp.
template <class T>
T lag_phi2(const T& r) noexcept {
  if (r < T(1) / T(2)) {
    // sum_{k>=0} (-r)^k / (k + 2)!
    T term = T(1) / T(2), sum = T(0);
    const T eps = std::numeric_limits<T>::epsilon();
    for (int k = 0; k < 200; ++k) {
      sum += term;
      term = -term * r / T(k + 3);
      if (!(term > eps * sum || -term > eps * sum)) break;
    }
    return sum;
  }
  return (expm1_of(-r) + r) / (r * r);
}

/// The first-order-hold weights of one step: y1 = decay y0 + weight_start s0 + weight_end s1.
template <class T>
struct lag_weights {
  T decay;         ///< e^{-h/Lambda}
  T weight_start;  ///< 1 - e^{-r} - r phi2(r)
  T weight_end;    ///< r phi2(r)
};

/// The weights for a step h >= 0 and lag Lambda >= 0 (same unit). Lambda = 0 (no lag): y = s,
/// {0, 0, 1}. h = 0: {1, 0, 0}.
template <class T>
lag_weights<T> lag_weights_of(const T& step, const T& lag) noexcept {
  using std::exp;
  if (!(lag > T(0))) return {T(0), T(0), T(1)};
  if (!(step > T(0))) return {T(1), T(0), T(0)};
  const T r = step / lag;
  const T end = r * lag_phi2(r);
  return {T(exp(-r)), T(-expm1_of(-r) - end), end};
}

/// One exact first-order-hold step (see the file comment).
template <class T>
T lag_step(const lag_weights<T>& w, const T& y0, const T& s0, const T& s1) noexcept {
  return w.decay * y0 + w.weight_start * s0 + w.weight_end * s1;
}

/// The direct transcription of the update, y1 = s1 - m Lambda + (y0 - s0 + m Lambda) e^{-h/Lambda},
/// kept to check the weights against it (it cancels m Lambda when h << Lambda).
template <class T>
T lag_step_direct(const T& y0, const T& s0, const T& s1, const T& step, const T& lag) noexcept {
  using std::exp;
  if (!(lag > T(0))) return s1;
  const T m_lag = (s1 - s0) / step * lag;
  return s1 - m_lag + (y0 - s0 + m_lag) * exp(-step / lag);
}

/// The output and its slope dy/dx inside a step, at x in [0, h], for s linear from s0 (x = 0) to
/// s1 (x = h) and y0 at x = 0: y(x) = s(x) - m Lambda (1 - e^{-x/Lambda}) + (y0 - s0)
/// e^{-x/Lambda}, y'(x) = (s(x) - y(x)) / Lambda; for Lambda = 0, y = s and y' = m. This is the
/// smooth function whose root places a crossing inside a step (sensor_physics/locator.hpp); linear
/// interpolation of y between the step's ends would not be exact.
template <class T>
struct lag_point {
  T value;
  T slope;
};

template <class T>
lag_point<T> lag_within_step(const T& y0, const T& s0, const T& s1, const T& step, const T& lag,
                             const T& x) noexcept {
  using std::exp;
  const T m = (s1 - s0) / step;
  const T s = s0 + m * x;
  if (!(lag > T(0))) return {s, m};
  const T decay = exp(-x / lag);
  const T y = s + m * lag * expm1_of(-x / lag) + (y0 - s0) * decay;
  return {y, T((s - y) / lag)};
}

/// The scan before a pulse from which the lag is integrated with y = s (MODEL §12): 20 Lambda,
/// after which the starting error has decayed by e^{-20} = 2.1e-9.
template <class T>
T lag_history(const T& lag) noexcept {
  return T(20) * lag;
}

/// The regularised lower incomplete gamma functions P(a, V) = gamma(a, V) / (a - 1)! for
/// a = 1, ..., count (count <= 64), into out[0..count-1]. V >= count: 1 - Q from the upward sum
/// Q(a) = e^{-V} sum_{i<a} V^i / i! (Q <= ~1/2 there, no cancellation); V < count: P(count) by
/// its series e^{-V} V^a / a! sum_j V^j / ((a+1)...(a+j)) (ratio < 1), then downwards by
/// P(a) = P(a+1) + e^{-V} V^a / a!, adding positive terms. Accuracy: a few ulp relative.
template <class T>
void regularised_lower_gamma(const T& v, int count, T* out) noexcept {
  using std::exp;
  const T eps = std::numeric_limits<T>::epsilon();
  const T e = exp(-v);
  if (v >= T(count)) {
    T term = e, q = T(0);  // term = e^{-V} V^i / i!
    for (int a = 1; a <= count; ++a) {
      q += term;
      out[a - 1] = T(1) - q;
      term = term * v / T(a);
    }
    return;
  }
  // terms[a] = e^{-V} V^a / a!, built upwards (downwards from a = count they would underflow
  // to 0 for a tiny V and never recover).
  T terms[65];
  terms[0] = e;
  for (int a = 1; a <= count; ++a) terms[a] = terms[a - 1] * v / T(a);
  T series = T(0), ratio = T(1);
  for (int j = 0; j < 400; ++j) {
    series += ratio;
    ratio = ratio * v / T(count + 1 + j);
    if (!(ratio > eps * series)) break;
  }
  T p = terms[count] * series;  // P(count)
  out[count - 1] = p;
  for (int a = count - 1; a >= 1; --a) {
    p += terms[a];
    out[a - 1] = p;
  }
}

/// The exact lag of a polynomial signal p over [chi - span, chi] started from y = 0:
///   int_0^span p(chi - u) e^{-u/Lambda} du / Lambda = sum_k (-Lambda)^k p^(k)(chi) P(k+1,
///   span/Lambda),
/// from p's Taylor series at chi (exact: it terminates). derivatives[k] = p^(k)(chi), k <
/// count (<= 64). The full output is e^{-span/Lambda} y(chi - span) plus this. Lambda = 0 returns
/// p(chi). For a linear p this is the first-order hold (lag_step). Stable for every span /
/// Lambda: for small V = span / Lambda the terms are the Taylor terms of int p / Lambda (P ~
/// V^{k+1} / (k+1)!), for large V the convergent expansion sum (-Lambda)^k p^(k) of a signal
/// smooth on the scale Lambda.
template <class T>
T lag_of_polynomial(const T* derivatives, int count, const T& span, const T& lag) noexcept {
  if (!(lag > T(0))) return derivatives[0];
  if (!(span > T(0))) return T(0);
  T gammas[64];
  regularised_lower_gamma(T(span / lag), count, gammas);
  T sum = T(0), power = T(1);
  for (int k = 0; k < count; ++k) {
    sum += power * derivatives[k] * gammas[k];
    power = -power * lag;
  }
  return sum;
}

}  // namespace conescan
