// Gauss-Legendre panels: the quadrature rule, and a polynomial known by its values at a panel's
// Gauss nodes turned into Legendre coefficients, so that its value, its derivatives and its
// integral can be evaluated anywhere in the panel. The sensor physics chain (sensor_physics.hpp)
// represents each smooth piece of a signal this way; the detector's lag of such a piece is exact
// (sensor_physics/detector.hpp, lag_of_polynomial).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "conescan/scalar.hpp"
#include "conescan/status.hpp"

namespace conescan {

/// The n-point Gauss-Legendre rule on [-1, 1]: nodes ascending, weights, and the matrix that
/// turns the values at the nodes into the Legendre coefficients of their interpolant,
///   c_m = (2m+1)/2 sum_i w_i P_m(x_i) f_i     (exact: the rule integrates degree <= 2n-1).
template <class T, int N>
struct gauss_legendre_rule {
  std::array<T, N> nodes;
  std::array<T, N> weights;
  std::array<std::array<T, N>, N> to_legendre;  ///< [m][i]
};

/// P_N(x) and its derivative, by the three-term recurrence.
template <class T>
void legendre_with_derivative(int n, const T& x, T& value, T& derivative) noexcept {
  T p0 = T(1), p1 = x;
  if (n == 0) {
    value = T(1);
    derivative = T(0);
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const T p2 = (T(2 * k - 1) * x * p1 - T(k - 1) * p0) / T(k);
    p0 = p1;
    p1 = p2;
  }
  value = p1;
  derivative = T(n) * (x * p1 - p0) / (x * x - T(1));
}

/// The n-point rule's nodes (ascending) and weights into nodes[0..n) and weights[0..n), for a
/// count known at run time (1 <= n): Newton's method on P_n from Tricomi's first guesses
/// cos(pi (i + 3/4) / (n + 1/2)), to 4 ulp (at most 100 steps; 3-6 in practice). Accuracy: nodes
/// and weights to a few ulp in every scalar type (tests/core/test_sensor_physics_lag.cpp against
/// the tabulated 10-point rule).
template <class T>
void gauss_legendre_nodes(int n, T* nodes, T* weights) noexcept {
  using std::abs;
  using std::cos;
  const T eps = std::numeric_limits<T>::epsilon();
  for (int i = 0; i < n; ++i) {
    T x = -cos(pi<T>() * (T(i) + T(3) / T(4)) / (T(n) + T(1) / T(2)));
    T value = T(0), derivative = T(1);
    for (int step = 0; step < 100; ++step) {
      legendre_with_derivative(n, x, value, derivative);
      const T dx = value / derivative;
      x -= dx;
      if (abs(dx) <= T(4) * eps) break;
    }
    legendre_with_derivative(n, x, value, derivative);
    nodes[i] = x;
    weights[i] = T(2) / ((T(1) - x * x) * derivative * derivative);
  }
}

/// The N-point rule with its matrix to Legendre coefficients (nodes and weights as
/// gauss_legendre_nodes).
template <class T, int N>
gauss_legendre_rule<T, N> gauss_legendre_rule_of() noexcept {
  static_assert(N >= 1 && N <= 64, "1 to 64 nodes");
  gauss_legendre_rule<T, N> r{};
  gauss_legendre_nodes(N, r.nodes.data(), r.weights.data());
  for (int i = 0; i < N; ++i) {
    T p0 = T(1), p1 = r.nodes[i];
    for (int m = 0; m < N; ++m) {
      const T pm = m == 0 ? p0 : p1;
      r.to_legendre[m][i] = T(2 * m + 1) / T(2) * r.weights[i] * pm;
      if (m >= 1) {
        const T p2 = (T(2 * m + 1) * r.nodes[i] * p1 - T(m) * p0) / T(m + 1);
        p0 = p1;
        p1 = p2;
      }
    }
  }
  return r;
}

/// The rule's quadrature of f over [a, b]: (b - a) / 2 times the weighted sum of f at the nodes
/// mapped to [a, b] (exact for polynomials of degree < 2N). f takes and returns T.
template <class T, int N, class F>
T gauss_integral(const gauss_legendre_rule<T, N>& rule, const T& a, const T& b, F&& f) noexcept {
  const T middle = (a + b) / integer_factor<T>(2), half = (b - a) / integer_factor<T>(2);
  T sum = T(0);
  for (int k = 0; k < N; ++k) sum += rule.weights[k] * f(T(middle + half * rule.nodes[k]));
  return sum * (b - a) / integer_factor<T>(2);
}

/// The composite rule: gauss_integral of f over each interval between consecutive ascending
/// cuts[0 .. n-1], empty intervals skipped, summed.
template <class T, int N, class F>
T gauss_integral_over_cuts(const gauss_legendre_rule<T, N>& rule, const T* cuts, int n,
                           F&& f) noexcept {
  T sum = T(0);
  for (int i = 0; i + 1 < n; ++i)
    if (cuts[i + 1] > cuts[i]) sum += gauss_integral(rule, cuts[i], cuts[i + 1], f);
  return sum;
}

/// A polynomial of degree < N on a panel [start, start + width], by its Legendre coefficients in
/// the panel's variable x = -1 + 2 (phi - start) / width.
template <class T, int N>
struct legendre_panel {
  T start;
  T width;
  std::array<T, N> coefficients;
};

/// The panel polynomial that takes the values f[i] at the rule's nodes.
template <class T, int N>
legendre_panel<T, N> legendre_panel_of(const gauss_legendre_rule<T, N>& rule, const T& start,
                                       const T& width, const T* f) noexcept {
  legendre_panel<T, N> p{start, width, {}};
  for (int m = 0; m < N; ++m) {
    T c = T(0);
    for (int i = 0; i < N; ++i) c += rule.to_legendre[m][i] * f[i];
    p.coefficients[m] = c;
  }
  return p;
}

/// The panel variable of phi.
template <class T, int N>
T panel_variable(const legendre_panel<T, N>& p, const T& phi) noexcept {
  return T(-1) + T(2) * (phi - p.start) / p.width;
}

/// The polynomial's value at phi (Clenshaw's recurrence for the Legendre series).
template <class T, int N>
T panel_value(const legendre_panel<T, N>& p, const T& phi) noexcept {
  const T x = panel_variable(p, phi);
  T b1 = T(0), b2 = T(0);
  for (int m = N - 1; m >= 0; --m) {
    // P_{m+1} = alpha_m P_m + beta_{m+1} P_{m-1}: alpha_m = (2m+1) x / (m+1), beta = -m/(m+1).
    const T b0 = p.coefficients[m] +
                 x * integer_factor<T>(2 * m + 1) / integer_factor<T>(m + 1) * b1 -
                 T(m + 1) / T(m + 2) * b2;
    b2 = b1;
    b1 = b0;
  }
  return b1;
}

/// The polynomial's value and its derivative in phi, from P_m and P_m' by their recurrences
/// (P_{m+1}' = P_{m-1}' + (2m+1) P_m).
template <class T, int N>
void panel_value_slope(const legendre_panel<T, N>& p, const T& phi, T& value, T& slope) noexcept {
  const T x = panel_variable(p, phi);
  T p_before = T(1), p_now = x, d_before = T(0), d_now = T(1);
  value = p.coefficients[0];
  slope = T(0);
  for (int m = 1; m < N; ++m) {
    value += p.coefficients[m] * p_now;
    slope += p.coefficients[m] * d_now;
    const T p_next = (x * integer_factor<T>(2 * m + 1) * p_now - p_before * integer_factor<T>(m)) /
                     integer_factor<T>(m + 1);
    const T d_next = d_before + p_now * integer_factor<T>(2 * m + 1);
    p_before = p_now;
    p_now = p_next;
    d_before = d_now;
    d_now = d_next;
  }
  slope = slope * T(2) / p.width;
}

/// The integral of the polynomial from the panel's start to phi:
///   int_{-1}^{x} P_0 = x + 1,  int_{-1}^{x} P_m = (P_{m+1}(x) - P_{m-1}(x)) / (2m + 1),
/// times width / 2.
template <class T, int N>
T panel_integral(const legendre_panel<T, N>& p, const T& phi) noexcept {
  const T x = panel_variable(p, phi);
  T sum = p.coefficients[0] * (x + T(1));
  T p_before = T(1), p_now = x;  // P_{m-1}, P_m
  for (int m = 1; m < N; ++m) {
    const T p_next = (x * integer_factor<T>(2 * m + 1) * p_now - p_before * integer_factor<T>(m)) /
                     integer_factor<T>(m + 1);
    sum += p.coefficients[m] * (p_next - p_before) / integer_factor<T>(2 * m + 1);
    p_before = p_now;
    p_now = p_next;
  }
  return sum * p.width / T(2);
}

/// Column k of the Legendre polynomials' derivative table at x: column[m] = P_m^(k)(x) for m in
/// [k, N), from the recurrence (m+1) P_{m+1}^(k) = (2m+1)(x P_m^(k) + k P_m^(k-1)) - m
/// P_{m-1}^(k), `previous` column k - 1 (unread for k = 0). Called for k = 0, 1, ... in turn with
/// the same `column`, it keeps the entries m < k zero (P_m^(k) = 0 there): the one home of the
/// recurrence, for panel_derivatives and the chain's table at the rule's nodes.
template <class T, std::size_t N>
void legendre_derivative_column(const T& x, int k, const std::array<T, N>& previous,
                                std::array<T, N>& column) noexcept {
  constexpr int n = static_cast<int>(N);
  if (k >= 1) column[k - 1] = T(0);  // P_{k-1}^(k): the recurrence for m = k reads it
  for (int m = k; m < n; ++m) {
    if (m == 0) {
      column[0] = T(1);
    } else if (m == 1) {
      column[1] = k == 0 ? x : T(1);
    } else {
      const int j = m - 1;  // P_{j+1} from P_j, P_{j-1}
      const T from_previous = k > 0 ? T(previous[j] * integer_factor<T>(k)) : T(0);
      column[m] = (T(x * column[j] + from_previous) * integer_factor<T>(2 * j + 1) -
                   column[j - 1] * integer_factor<T>(j)) /
                  integer_factor<T>(j + 1);
    }
  }
}

/// The polynomial's derivatives d^k p / dphi^k at phi for k = 0 .. count-1 (count in [1, N],
/// the default all N), into out[0..count-1], from the derivative recurrences
/// (legendre_derivative_column), scaled by (2 / width)^k. Column k needs only m >= k (P_m^(k) = 0
/// below), and a caller that reads the first few derivatives asks for those alone: the table's
/// cost falls from N^2 values to about count N - count^2 / 2 (a pencil's chain spent 40 % of its
/// time here on all N). The values are those of the whole table to the bit (the entries skipped
/// are exact zeros in it).
template <class T, int N>
void panel_derivatives(const legendre_panel<T, N>& p, const T& phi, T* out,
                       int count = N) noexcept {
  const T x = panel_variable(p, phi);
  // column[m] = P_m^(k)(x) for the current k; previous = P_m^(k-1)(x); entries m < k are 0.
  std::array<T, N> previous{}, column{};
  const T scale = T(2) / p.width;
  T factor = T(1);
  for (int k = 0; k < count; ++k) {
    legendre_derivative_column(x, k, previous, column);
    T sum = T(0);
    for (int m = k; m < N; ++m) sum += p.coefficients[m] * column[m];
    out[k] = sum * factor;
    factor = factor * scale;
    previous = column;
  }
}

}  // namespace conescan
