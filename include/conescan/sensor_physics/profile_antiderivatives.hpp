// The repeated antiderivatives of the limb's shape (MODEL §12, "Radiance") in the scaled height
// x = (delta - delta50) / H: with l(x) = 1 - exp(-ln 2 e^{-x}) (sensor_physics/profile.hpp),
//   l_(0) = l,   l_(k)(x) = -int_x^inf l_(k-1)(t) dt   (k = 1 .. 5),
// so that l_(k)' = l_(k-1) and every l_(k) vanishes far above the knee. They turn an integral of
// the profile against a polynomial weight into a few evaluations (repeated integration by parts,
// exact for a polynomial p of degree < 5):
//   int_a^b l(x) p(x) dx = [ sum_k (-1)^k p^(k)(x) l_(k+1)(x) ]_a^b,
// which is how the fast method (sensor_physics/fast.hpp) averages the profile across its field
// without resolving the knee by quadrature.
//
// How they are evaluated (one table for every head: in x the shape is universal):
//  - above x_high = 8 (v = ln 2 e^{-x} <= 2.3e-4), the series from l = sum_{n>=1} (-1)^{n+1}
//    v^n / n! integrated term by term: l_(k) = (-1)^k sum_{n>=1} (-1)^{n+1} v^n / (n! n^k), a
//    few terms;
//  - between x_low and x_high, Chebyshev series on panels of at most 1/2 in x (13 terms; l is
//    bounded in the strip |Im x| < pi/2, so the series converge like 9^-n: the 13th coefficient
//    is below 1e-15 of the first on every panel, measured), built once by
//    integrating l's interpolant term by term from the right, each panel's right-end values
//    taken from its right neighbour (the series at x_high for the first);
//  - below x_low = ln(ln 2 / ln(2 / eps)) (radiance_profile's x_saturated, -3.97 in double),
//    where l is 1 to rounding, exactly the polynomials that continue them:
//    l_(k)(x) = sum_{j<k} l_(k-j)(x_low) t^j / j! + t^k / k!, t = x - x_low.
// Accuracy (tests/test_sensor_physics_fast.cpp, against long double quadrature of the
// definition): ~1e-15 relative to max(1, |l_(k)|) in double.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "conescan/sensor_physics/profile.hpp"
#include "conescan/scalar_expm1.hpp"
#include "conescan/status.hpp"

namespace conescan {

/// The table of l_(1) .. l_(5): Chebyshev coefficients per panel, and the values at x_low.
template <class T>
struct limb_antiderivatives {
  static constexpr int orders = 5;       ///< l_(1) .. l_(5)
  static constexpr int terms = 13;       ///< Chebyshev terms per panel and order
  static constexpr int max_panels = 40;  ///< enough for x_low down to -12 (eps ~ 1e-70000)
  int panels;
  T x_low, x_high;  ///< the table's range; outside it the continuation and the series
  T panel_width;
  T ln2;
  std::array<std::array<std::array<T, terms>, orders>, max_panels> chebyshev;  ///< [p][k-1][j]
  std::array<T, orders> at_low;                                                ///< l_(k)(x_low)
  status state;  ///< ok; invalid when T's epsilon puts x_low beyond the table
};

namespace antiderivative_detail {

/// l_(1) .. l_(5) at x >= x_high by their series in v = ln 2 e^{-x} (terms to the scalar's
/// epsilon: 5 in double at x_high; at most 60).
template <class T>
void series(const T& ln2, const T& x, T out[5]) noexcept {
  using std::exp;
  const T v = ln2 * exp(-x);
  const T eps = std::numeric_limits<T>::epsilon();
  T sums[5] = {T(0), T(0), T(0), T(0), T(0)};
  T term = v;  // (-1)^{n+1} v^n / n!
  for (int n = 1; n <= 60; ++n) {
    const T inverse = T(1) / T(n);
    T scaled = term;
    for (int k = 0; k < 5; ++k) {
      scaled = scaled * inverse;
      sums[k] += scaled;
    }
    if (!(term > eps * v || -term > eps * v)) break;
    term = -term * v / T(n + 1);
  }
  // l_(k) = (-1)^k sum_k.
  for (int k = 0; k < 5; ++k) out[k] = k % 2 == 0 ? T(-sums[k]) : sums[k];
}

/// Clenshaw's sum of a Chebyshev series at y in [-1, 1].
template <class T, int N>
T chebyshev_value(const std::array<T, N>& c, const T& y) noexcept {
  T b1 = T(0), b2 = T(0);
  const T two_y = y + y;
  for (int j = N - 1; j >= 1; --j) {
    const T b0 = c[j] + two_y * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + y * b1 - b2;
}

/// The antiderivative's coefficients of a Chebyshev series on a panel of half-width hw, the
/// constant chosen so that it takes `right` at the panel's right end (y = 1). The term of degree
/// N (beyond the table) is dropped: the series has converged there.
template <class T, int N>
std::array<T, N> chebyshev_antiderivative(const std::array<T, N>& a, const T& hw,
                                          const T& right) noexcept {
  std::array<T, N> c{};
  // int T_0 = T_1, int T_1 = T_2 / 4, int T_k = T_{k+1} / (2 (k+1)) - T_{k-1} / (2 (k-1)).
  for (int k = 0; k < N; ++k) {
    if (k == 0) {
      c[1] += a[0];
    } else if (k == 1) {
      if (N > 2) c[2] += a[1] / T(4);
    } else {
      if (k + 1 < N) c[k + 1] += a[k] / T(2 * (k + 1));
      c[k - 1] -= a[k] / T(2 * (k - 1));
    }
  }
  T sum = T(0);
  for (int k = 0; k < N; ++k) {
    c[k] = c[k] * hw;
    if (k > 0) sum += c[k];
  }
  c[0] = right - sum;  // T_k(1) = 1
  return c;
}

/// The series' value at the panel's left end (y = -1): T_k(-1) = (-1)^k.
template <class T, int N>
T chebyshev_left(const std::array<T, N>& c) noexcept {
  T sum = T(0);
  for (int k = 0; k < N; ++k) sum += (k % 2 == 0) ? c[k] : T(-c[k]);
  return sum;
}

}  // namespace antiderivative_detail

/// The table (once per scalar type; every head shares it, see the file comment). invalid only
/// for a scalar whose epsilon puts x_low below -12.
template <class T>
limb_antiderivatives<T> limb_antiderivatives_of() noexcept {
  using std::ceil;
  using std::cos;
  using std::exp;
  using std::log;
  using namespace antiderivative_detail;
  constexpr int N = limb_antiderivatives<T>::terms;
  limb_antiderivatives<T> t{};
  t.ln2 = log(T(2));
  const T eps = std::numeric_limits<T>::epsilon();
  t.x_low = log(t.ln2 / T(log(T(2) / eps)));  // radiance_profile's x_saturated
  t.x_high = T(8);
  const T count = ceil((t.x_high - t.x_low) * T(2));
  if (!(count <= T(limb_antiderivatives<T>::max_panels)) || !(count >= T(1))) {
    t.state = status::invalid;
    return t;
  }
  t.panels = static_cast<int>(static_cast<long double>(count));
  t.panel_width = (t.x_high - t.x_low) / T(t.panels);
  const T hw = t.panel_width / T(2);
  T right[5];
  series(t.ln2, t.x_high, right);
  for (int p = t.panels - 1; p >= 0; --p) {
    const T mid = t.x_low + (T(p) + T(1) / T(2)) * t.panel_width;
    // l at the Chebyshev points y_i = cos(pi (i + 1/2) / N), then its coefficients (a_0 halved).
    std::array<T, N> f{}, a{};
    for (int i = 0; i < N; ++i) {
      const T y = cos(pi<T>() * (T(i) + T(1) / T(2)) / T(N));
      f[i] = -expm1_of(T(-t.ln2 * exp(T(-(mid + hw * y)))));
    }
    for (int j = 0; j < N; ++j) {
      T sum = T(0);
      for (int i = 0; i < N; ++i) sum += f[i] * cos(pi<T>() * T(j) * (T(i) + T(1) / T(2)) / T(N));
      a[j] = sum * T(2) / T(N);
    }
    a[0] = a[0] / T(2);
    for (int k = 0; k < 5; ++k) {
      a = chebyshev_antiderivative<T, N>(a, hw, right[k]);
      t.chebyshev[p][k] = a;
      right[k] = chebyshev_left<T, N>(a);
    }
  }
  for (int k = 0; k < 5; ++k) t.at_low[k] = right[k];
  t.state = status::ok;
  return t;
}

/// l_(1)(x) .. l_(5)(x) into out[0..4] (dimensionless; x = (delta - delta50) / H). Any finite x;
/// the table must be ok.
template <class T>
void limb_antiderivatives_at(const limb_antiderivatives<T>& t, const T& x, T out[5]) noexcept {
  using std::floor;
  if (x >= t.x_high) {
    antiderivative_detail::series(t.ln2, x, out);
    return;
  }
  if (x < t.x_low) {
    // l = 1 below x_low: the Taylor polynomials of the values there, exact.
    const T d = x - t.x_low;
    // l_(k)(x_low + d) = sum_{j<k} l_(k-j)(x_low) d^j / j! + d^k / k!, by Horner in d.
    for (int k = 0; k < 5; ++k) {
      T sum = T(1);
      for (int j = k + 1; j >= 1; --j) sum = t.at_low[k + 1 - j] + d * sum / T(j);
      out[k] = sum;
    }
    return;
  }
  const T position = (x - t.x_low) / t.panel_width;
  int p = static_cast<int>(static_cast<long double>(floor(position)));
  if (p > t.panels - 1) p = t.panels - 1;
  if (p < 0) p = 0;
  const T y = T(2) * (position - T(p)) - T(1), two_y = y + y;
  // Clenshaw's recurrence for the five series at once: independent chains, interleaved. Each
  // integration divides the j-th coefficient by ~j/hw, so l_(k) needs fewer terms than l_(1)
  // for the same relative error: a term less every second order (measured: the dropped terms
  // change no value by more than 2e-15 of max(1, |l_(k)|)).
  constexpr int N = limb_antiderivatives<T>::terms;
  const auto& c = t.chebyshev[p];
  T b1[5] = {T(0), T(0), T(0), T(0), T(0)}, b2[5] = {T(0), T(0), T(0), T(0), T(0)};
  for (int j = N - 1; j >= 1; --j)
    for (int k = 0; k < 5; ++k) {
      if (2 * j >= 2 * N - k) continue;
      const T b0 = c[k][j] + two_y * b1[k] - b2[k];
      b2[k] = b1[k];
      b1[k] = b0;
    }
  for (int k = 0; k < 5; ++k) out[k] = c[k][0] + y * b1[k] - b2[k];
}

}  // namespace conescan
