// A smooth function of up to three variables on a box, known by its values at the box's tensor
// grid of Chebyshev points (first kind) and evaluated anywhere in the box as the tensor Chebyshev
// series that interpolates them. The scene tabulates the sensor physics' crossing shifts this way
// over the range of distances and nadir directions its rows visit (docs/SENSOR_PHYSICS.md, "The
// table", src/scene/physics_table.hpp): a row then costs one series evaluation, not the chain.
//
// Domain: a box with lo <= hi in each variable (lo == hi: the variable is held, one node), at
// most 64 nodes a variable. The series converges geometrically for a function analytic on the
// box; chebyshev_box_build chooses the nodes from sweeps and measures the result against the
// function at the box's corners and 16 points inside (its report's worst_check), and gives up
// (ok false) rather than return a series it has not seen hold. Measured: exp(x) cos(y) to a
// thousand ulp in float, double, long double and the ADL scalar; the physics shifts to 1e-8 deg
// (tests/test_physics_table.cpp). Outside the box the series extrapolates: `contains` says where
// it holds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>

#include "conescan/scalar.hpp"

namespace conescan {

/// Capacity: at most `Capacity` nodes in all, `Outputs` values per node.
template <class T, int Outputs, int Capacity>
struct chebyshev_box {
  std::array<int, 3> nodes{{1, 1, 1}};  ///< per variable, >= 1
  std::array<T, 3> lo{}, hi{};
  /// c[((i * n1 + j) * n2 + k) * Outputs + o]: the coefficient of T_i(x0) T_j(x1) T_k(x2) for
  /// output o (the outputs side by side: one pass of the evaluation serves them all).
  std::array<T, Capacity * Outputs> coefficients{};

  int count() const noexcept { return nodes[0] * nodes[1] * nodes[2]; }

  /// Whether x lies in the box (its held variables within `held_slack` of their value).
  bool contains(const std::array<T, 3>& x, const T& held_slack) const noexcept {
    for (int d = 0; d < 3; ++d) {
      if (nodes[d] == 1) {
        using std::abs;
        if (!(abs(x[d] - lo[d]) <= held_slack)) return false;
      } else if (!(x[d] >= lo[d] && x[d] <= hi[d])) {
        return false;
      }
    }
    return true;
  }
};

namespace chebyshev_detail {

/// The k-th of n Chebyshev points of the first kind on [lo, hi] (its middle where n == 1).
template <class T>
T node(int k, int n, const T& lo, const T& hi) noexcept {
  using std::cos;
  const T middle = (lo + hi) / T(2), half = (hi - lo) / T(2);
  if (n == 1) return middle;
  return middle + half * T(cos(pi<T>() * (T(2 * k + 1)) / T(2 * n)));
}

/// T_0 .. T_{n-1} at x mapped from [lo, hi] to [-1, 1].
template <class T>
void basis(int n, const T& x, const T& lo, const T& hi, T* out) noexcept {
  const T t = n == 1 ? T(0) : (T(2) * x - lo - hi) / (hi - lo);
  out[0] = T(1);
  if (n > 1) out[1] = t;
  for (int k = 2; k < n; ++k) out[k] = T(2) * t * out[k - 1] - out[k - 2];
}

/// One variable's discrete cosine transform, in place over the table: values at the nodes along
/// variable d become that variable's Chebyshev coefficients, c_m = (2 - [m = 0]) / n
/// sum_k f_k cos(pi m (k + 1/2) / n).
template <class T, std::size_t Size>
void transform(std::array<T, Size>& v, const std::array<int, 3>& n, int d, int output,
               int outputs) noexcept {
  using std::cos;
  const int stride = d == 0 ? n[1] * n[2] : d == 1 ? n[2] : 1;
  const int m_count = n[d];
  if (m_count == 1) return;
  std::array<T, 64> line{};
  const int total = n[0] * n[1] * n[2];
  for (int start = 0; start < total; ++start) {
    if ((start / stride) % m_count != 0) continue;  // one line per start on the variable's axis
    for (int m = 0; m < m_count; ++m) {
      T sum = T(0);
      for (int k = 0; k < m_count; ++k)
        sum += v[(start + k * stride) * outputs + output] *
               T(cos(pi<T>() * T(m) * (T(2 * k + 1)) / T(2 * m_count)));
      line[m] = sum * T(m == 0 ? 1 : 2) / T(m_count);
    }
    for (int m = 0; m < m_count; ++m) v[(start + m * stride) * outputs + output] = line[m];
  }
}

}  // namespace chebyshev_detail

/// Fills `box` (its nodes, lo and hi set by the caller; at most 64 nodes a variable and
/// `Capacity` in all) from f(x, out), which writes the Outputs values at x and returns whether
/// they exist. Returns false, the box unusable, where f fails at any node or a value is not
/// finite.
template <class T, int Outputs, int Capacity, class F>
bool chebyshev_box_fit(chebyshev_box<T, Outputs, Capacity>& box, F&& f) {
  const std::array<int, 3>& n = box.nodes;
  if (n[0] < 1 || n[1] < 1 || n[2] < 1 || n[0] > 64 || n[1] > 64 || n[2] > 64 ||
      box.count() > Capacity)
    return false;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const std::array<T, 3> x{chebyshev_detail::node(i, n[0], box.lo[0], box.hi[0]),
                                 chebyshev_detail::node(j, n[1], box.lo[1], box.hi[1]),
                                 chebyshev_detail::node(k, n[2], box.lo[2], box.hi[2])};
        std::array<T, Outputs> out{};
        if (!f(x, out)) return false;
        for (int o = 0; o < Outputs; ++o) {
          if (!is_finite(out[o])) return false;
          box.coefficients[((i * n[1] + j) * n[2] + k) * Outputs + o] = out[o];
        }
      }
  for (int o = 0; o < Outputs; ++o)
    for (int d = 0; d < 3; ++d) chebyshev_detail::transform(box.coefficients, n, d, o, Outputs);
  return true;
}

/// The interpolant's Outputs values at x (meant for x inside the box: `contains`).
template <class T, int Outputs, int Capacity>
std::array<T, Outputs> chebyshev_box_value(const chebyshev_box<T, Outputs, Capacity>& box,
                                           const std::array<T, 3>& x) noexcept {
  const std::array<int, 3>& n = box.nodes;
  T b0[64], b1[64], b2[64];
  chebyshev_detail::basis(n[0], x[0], box.lo[0], box.hi[0], b0);
  chebyshev_detail::basis(n[1], x[1], box.lo[1], box.hi[1], b1);
  chebyshev_detail::basis(n[2], x[2], box.lo[2], box.hi[2], b2);
  // Nested sums, innermost over x2, every output in the same pass.
  std::array<T, Outputs> value{};
  const T* c = box.coefficients.data();
  for (int i = 0; i < n[0]; ++i) {
    std::array<T, Outputs> sum_j{};
    for (int j = 0; j < n[1]; ++j) {
      std::array<T, Outputs> sum_k{};
      for (int k = 0; k < n[2]; ++k, c += Outputs)
        for (int o = 0; o < Outputs; ++o) sum_k[o] += c[o] * b2[k];
      for (int o = 0; o < Outputs; ++o) sum_j[o] += sum_k[o] * b1[j];
    }
    for (int o = 0; o < Outputs; ++o) value[o] += sum_j[o] * b0[i];
  }
  return value;
}

}  // namespace conescan

namespace conescan {

/// What chebyshev_box_nodes and chebyshev_box_build did: whether the box holds the function to
/// the tolerance, the nodes each variable needs (0: more than 64, or the budget ran out first),
/// the evaluations spent and the worst difference from the function at the check points.
template <class T>
struct chebyshev_box_report {
  bool ok = false;
  std::array<int, 3> nodes{{1, 1, 1}};
  long evaluations = 0;
  T worst_check = T(0);
};

namespace chebyshev_detail {

/// The node counts a variable's sweep tries, in order.
inline constexpr int schedule[] = {3,  4,  5,  6,  7,  8,  10, 12, 14, 16,
                                   18, 21, 24, 28, 32, 37, 43, 50, 57, 64};

/// The tail of f along variable d through the box's middle with n nodes (3 to 64): |c_{n-2}| +
/// |c_{n-1}| of each output's series in that variable alone (transform's), the largest over
/// outputs. false where f fails or a value is not finite.
template <class T, int Outputs, class F>
bool sweep_tail(const std::array<T, 3>& lo, const std::array<T, 3>& hi, int d, int n, F& f,
                T& tail) {
  using std::abs;
  std::array<T, 64 * Outputs> values{};
  for (int k = 0; k < n; ++k) {
    std::array<T, 3> x{};
    for (int e = 0; e < 3; ++e) x[e] = e == d ? node(k, n, lo[d], hi[d]) : (lo[e] + hi[e]) / T(2);
    std::array<T, Outputs> out{};
    if (!f(x, out)) return false;
    for (int o = 0; o < Outputs; ++o) {
      if (!is_finite(out[o])) return false;
      values[k * Outputs + o] = out[o];
    }
  }
  tail = T(0);
  for (int o = 0; o < Outputs; ++o) {
    chebyshev_detail::transform(values, std::array<int, 3>{{n, 1, 1}}, 0, o, Outputs);
    const T sum = abs(values[(n - 2) * Outputs + o]) + abs(values[(n - 1) * Outputs + o]);
    if (!(sum <= tail)) tail = sum;
  }
  return true;
}

/// The difference between f and the box's series at x, the largest over outputs, or NaN where f
/// fails.
template <class T, int Outputs, int Capacity, class F>
T difference_at(const chebyshev_box<T, Outputs, Capacity>& box, F& f, const std::array<T, 3>& x) {
  using std::abs;
  std::array<T, Outputs> exact{};
  if (!f(x, exact)) return not_a_number<T>();
  const std::array<T, Outputs> fitted = chebyshev_box_value(box, x);
  T worst = T(0);
  for (int o = 0; o < Outputs; ++o) {
    const T difference = abs(fitted[o] - exact[o]);
    if (!(difference <= worst)) worst = difference;
  }
  return worst;
}

/// Compares f with the box's series at the box's corners (where a series is furthest from its
/// nodes: first-kind points do not reach the edges) and at `checks` points spread over it: a
/// Weyl sequence in integers (k times odd multipliers near 2^16 times the plastic and golden
/// ratios' fractional parts, modulo 2^16), exact in every scalar. The worst difference (NaN
/// where f fails) and the evaluations spent.
template <class T, int Outputs, int Capacity, class F>
T check_box(const chebyshev_box<T, Outputs, Capacity>& box, F& f, int checks, long& evaluations) {
  T worst = T(0);
  auto keep = [&worst](const T& d) {
    if (!(d <= worst)) worst = d;
  };
  for (int corner = 0; corner < 8; ++corner) {
    bool repeated = false;  // a held variable has one side: its corners coincide
    std::array<T, 3> x{};
    for (int d = 0; d < 3; ++d) {
      const bool high = (corner >> d) & 1;
      repeated = repeated || (high && box.nodes[d] == 1);
      x[d] = high ? box.hi[d] : box.lo[d];
    }
    if (repeated) continue;
    ++evaluations;
    keep(difference_at(box, f, x));
  }
  const long multipliers[3] = {40503, 49471, 37345};
  for (int k = 1; k <= checks; ++k) {
    std::array<T, 3> x{};
    for (int d = 0; d < 3; ++d)
      x[d] = box.lo[d] + (box.hi[d] - box.lo[d]) * T((k * multipliers[d]) % 65536) / T(65536);
    ++evaluations;
    keep(difference_at(box, f, x));
  }
  return worst;
}

}  // namespace chebyshev_detail

/// The nodes variable d of f on [lo, hi] needs for `tolerance` (absolute, every output): a count
/// of the schedule (3, 4, 5, 6, 7, 8, 10, ... 64) whose sweep through the box's middle has a tail
/// within a quarter of the tolerance (the fit is checked after: chebyshev_box_build). From the
/// second sweep on, the tails' geometric decay says how many nodes the tolerance needs, and the
/// sweeps jump to the first count of the schedule at least that large (then step on where it was
/// too few); 1 for a held variable (lo == hi); 0 where it needs more than 64, f fails, or the
/// sweeps would pass `budget` evaluations. Adds the evaluations spent to `evaluations`.
template <class T, int Outputs, class F>
int chebyshev_variable_nodes(const std::array<T, 3>& lo, const std::array<T, 3>& hi, int d, F&& f,
                             const T& tolerance, long budget, long& evaluations) {
  using std::log;
  if (lo[d] == hi[d]) return 1;
  const int* const begin = std::begin(chebyshev_detail::schedule);
  const int* const end = std::end(chebyshev_detail::schedule);
  const int* next = begin;
  int last_n = 0;
  T last_tail = T(0);
  while (next != end) {
    const int n = *next;
    T tail = T(0);
    if (evaluations + n > budget) return 0;
    evaluations += n;
    if (!chebyshev_detail::sweep_tail<T, Outputs>(lo, hi, d, n, f, tail)) return 0;
    // A quarter of the tolerance: the fit's error between the sweep's line and the box's corners
    // (the other variables' terms) is left the rest.
    const T target = tolerance / T(4);
    if (tail <= target) return n;
    ++next;
    if (last_n > 0 && tail > T(0) && tail < last_tail / T(2)) {
      // tail ~ exp(-rate n): the nodes where it reaches the target, at most twice as many as
      // now (a decay read from two sweeps is rough; an even or odd function's tails stall).
      const T rate = log(last_tail / tail) / T(n - last_n);
      const T needed = T(n) + log(tail / target) / rate;
      while (next + 1 != end && T(*next) < needed && *next < 2 * n) ++next;
    }
    last_n = n;
    last_tail = tail;
  }
  return 0;
}

/// chebyshev_variable_nodes of each variable (ok false where one gets 0).
template <class T, int Outputs, class F>
chebyshev_box_report<T> chebyshev_box_nodes(const std::array<T, 3>& lo, const std::array<T, 3>& hi,
                                            F&& f, const T& tolerance, long budget) {
  chebyshev_box_report<T> report;
  report.ok = true;
  for (int d = 0; d < 3; ++d) {
    report.nodes[d] =
        chebyshev_variable_nodes<T, Outputs>(lo, hi, d, f, tolerance, budget, report.evaluations);
    if (report.nodes[d] == 0) report.ok = false;
  }
  return report;
}

/// Fits `box` to f on [lo, hi] with `nodes` (chebyshev_box_nodes') to `tolerance` (absolute,
/// every output): one fit, then f against the series at the box's corners and `checks` points
/// inside it, every difference within the tolerance; where one is not, every varying variable
/// takes the count of the schedule past a quarter more nodes and the box is fitted and checked
/// again (twice at most). Gives up (ok false) where f fails, a variable would need more than 64
/// nodes, the box more than Capacity, or the evaluations would pass `budget` (the caller's price
/// for the table: f is the slow method).
template <class T, int Outputs, int Capacity, class F>
chebyshev_box_report<T> chebyshev_box_fit_checked(chebyshev_box<T, Outputs, Capacity>& box,
                                                  const std::array<T, 3>& lo,
                                                  const std::array<T, 3>& hi,
                                                  const std::array<int, 3>& nodes, F&& f,
                                                  const T& tolerance, long budget,
                                                  int checks = 16) {
  chebyshev_box_report<T> report;
  box.lo = lo;
  box.hi = hi;
  box.nodes = nodes;
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (box.count() > Capacity || report.evaluations + box.count() + checks + 8 > budget)
      return report;
    report.evaluations += box.count();
    if (!chebyshev_box_fit(box, f)) return report;
    report.worst_check = chebyshev_detail::check_box(box, f, checks, report.evaluations);
    report.nodes = box.nodes;
    if (report.worst_check <= tolerance) {
      report.ok = true;
      return report;
    }
    for (int d = 0; d < 3; ++d) {  // a quarter more nodes, at least one
      if (box.nodes[d] == 1) continue;
      const int* next =
          std::upper_bound(std::begin(chebyshev_detail::schedule),
                           std::end(chebyshev_detail::schedule), box.nodes[d] + box.nodes[d] / 4);
      if (next == std::end(chebyshev_detail::schedule)) return report;
      box.nodes[d] = *next;
    }
  }
  return report;
}

/// chebyshev_box_nodes, then chebyshev_box_fit_checked: the box of f on [lo, hi] to
/// `tolerance` within `budget` evaluations in all.
template <class T, int Outputs, int Capacity, class F>
chebyshev_box_report<T> chebyshev_box_build(chebyshev_box<T, Outputs, Capacity>& box,
                                            const std::array<T, 3>& lo, const std::array<T, 3>& hi,
                                            F&& f, const T& tolerance, long budget,
                                            int checks = 16) {
  const chebyshev_box_report<T> plan =
      chebyshev_box_nodes<T, Outputs>(lo, hi, f, tolerance, budget);
  if (!plan.ok) return plan;
  chebyshev_box_report<T> report = chebyshev_box_fit_checked(box, lo, hi, plan.nodes, f, tolerance,
                                                             budget - plan.evaluations, checks);
  report.evaluations += plan.evaluations;
  return report;
}

}  // namespace conescan
