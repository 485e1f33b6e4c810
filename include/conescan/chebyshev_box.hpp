// A smooth function of a few variables (three unless said) on a box, known by its values at the
// box's tensor grid of Chebyshev points (first kind) and evaluated anywhere in the box as the
// tensor Chebyshev series that interpolates them. The scene tabulates the sensor physics' crossing
// shifts this way over the range of distances and nadir directions its rows visit
// (docs/SENSOR_PHYSICS.md, "The table", src/simulation/physics_table.hpp): a row then costs one
// series evaluation, not the chain.
//
// Domain: a box with lo <= hi in each variable (lo == hi: the variable is held, one node), at
// most 64 nodes a variable. The series converges geometrically for a function analytic on the
// box; chebyshev_box_build chooses the nodes from sweeps and measures the result against the
// function at the box's corners and 16 points inside (its report's worst_check), and gives up
// (ok false) rather than return a series it has not seen hold. Measured: exp(x) cos(y) to a
// thousand ulp in float, double, long double and the ADL scalar; the physics shifts to 1e-8 deg
// (tests/simulation/test_physics_table.cpp). Outside the box the series extrapolates: `contains`
// says where it holds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>

#include "conescan/scalar.hpp"

namespace conescan {

/// Capacity: at most `Capacity` nodes in all, `Outputs` values per node, `Dims` variables.
template <class T, int Outputs, int Capacity, int Dims = 3>
struct chebyshev_box {
  std::array<int, Dims> nodes = ones();  ///< per variable, >= 1
  std::array<T, Dims> lo{}, hi{};
  /// c[((i * n1 + j) * n2 + k) * Outputs + o] (three variables; the last varies fastest): the
  /// coefficient of T_i(x0) T_j(x1) T_k(x2) for output o (the outputs side by side: one pass of
  /// the evaluation serves them all).
  std::array<T, Capacity * Outputs> coefficients{};

  static constexpr std::array<int, Dims> ones() noexcept {
    std::array<int, Dims> n{};
    for (int& m : n) m = 1;
    return n;
  }
  int count() const noexcept {
    int c = 1;
    for (int m : nodes) c *= m;
    return c;
  }

  /// Whether x lies in the box (its held variables within `held_slack` of their value; a
  /// variable with one node over a range, the series constant in it, within the range and the
  /// slack).
  bool contains(const std::array<T, std::size_t{Dims}>& x, const T& held_slack) const noexcept {
    for (int d = 0; d < Dims; ++d) {
      if (nodes[d] == 1 && lo[d] == hi[d]) {
        using std::abs;
        if (!(abs(x[d] - lo[d]) <= held_slack)) return false;
      } else if (nodes[d] == 1) {
        if (!(x[d] >= lo[d] - held_slack && x[d] <= hi[d] + held_slack)) return false;
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
template <class T, std::size_t Size, std::size_t Dims>
void transform(std::array<T, Size>& v, const std::array<int, Dims>& n, int d, int output,
               int outputs) noexcept {
  using std::cos;
  int stride = 1, total = 1;
  for (std::size_t e = 0; e < Dims; ++e) {
    total *= n[e];
    if (static_cast<int>(e) > d) stride *= n[e];
  }
  const int m_count = n[d];
  if (m_count == 1) return;
  std::array<T, 64> line{};
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
template <class T, int Outputs, int Capacity, int Dims, class F>
bool chebyshev_box_fit(chebyshev_box<T, Outputs, Capacity, Dims>& box, F&& f) {
  const std::array<int, Dims>& n = box.nodes;
  for (int m : n)
    if (m < 1 || m > 64) return false;
  if (box.count() > Capacity) return false;
  // The nodes in the coefficients' order (the last variable fastest), by a mixed-radix counter.
  std::array<int, Dims> at{};
  for (int flat = 0; flat < box.count(); ++flat) {
    std::array<T, Dims> x{};
    for (int d = 0; d < Dims; ++d) x[d] = chebyshev_detail::node(at[d], n[d], box.lo[d], box.hi[d]);
    std::array<T, Outputs> out{};
    if (!f(x, out)) return false;
    for (int o = 0; o < Outputs; ++o) {
      if (!is_finite(out[o])) return false;
      box.coefficients[flat * Outputs + o] = out[o];
    }
    for (int d = Dims - 1; d >= 0 && ++at[d] == n[d]; --d) at[d] = 0;
  }
  for (int o = 0; o < Outputs; ++o)
    for (int d = 0; d < Dims; ++d) chebyshev_detail::transform(box.coefficients, n, d, o, Outputs);
  return true;
}

namespace chebyshev_detail {

/// The nested sums of the series from variable D on (the last innermost), added to `out`.
template <int D, class T, int Outputs, int Dims>
void nested_sum(const std::array<int, Dims>& n, const T (*b)[64], const T*& c,
                std::array<T, Outputs>& out) noexcept {
  if constexpr (D == Dims - 1) {
    for (int k = 0; k < n[D]; ++k, c += Outputs)
      for (int o = 0; o < Outputs; ++o) out[o] += c[o] * b[D][k];
  } else {
    for (int i = 0; i < n[D]; ++i) {
      std::array<T, Outputs> inner{};
      nested_sum<D + 1, T, Outputs, Dims>(n, b, c, inner);
      for (int o = 0; o < Outputs; ++o) out[o] += inner[o] * b[D][i];
    }
  }
}

}  // namespace chebyshev_detail

/// The interpolant's Outputs values at x (meant for x inside the box: `contains`).
template <class T, int Outputs, int Capacity, int Dims>
std::array<T, Outputs> chebyshev_box_value(const chebyshev_box<T, Outputs, Capacity, Dims>& box,
                                           const std::array<T, std::size_t{Dims}>& x) noexcept {
  T b[Dims][64];
  for (int d = 0; d < Dims; ++d)
    chebyshev_detail::basis(box.nodes[d], x[d], box.lo[d], box.hi[d], b[d]);
  // Nested sums, innermost over the last variable, every output in the same pass.
  std::array<T, Outputs> value{};
  const T* c = box.coefficients.data();
  chebyshev_detail::nested_sum<0, T, Outputs, Dims>(box.nodes, b, c, value);
  return value;
}

}  // namespace conescan

namespace conescan {

/// What chebyshev_box_nodes and chebyshev_box_build did: whether the box holds the function to
/// the tolerance, the nodes each variable needs (0: more than 64, or the budget ran out first),
/// the evaluations spent and the worst difference from the function at the check points.
template <class T, int Dims = 3>
struct chebyshev_box_report {
  bool ok = false;
  std::array<int, Dims> nodes = chebyshev_box<T, 1, 1, Dims>::ones();
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
template <class T, int Outputs, std::size_t Dims, class F>
bool sweep_tail(const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, int d, int n, F& f,
                T& tail, T* last = nullptr) {
  using std::abs;
  std::array<T, 64 * Outputs> values{};
  for (int k = 0; k < n; ++k) {
    std::array<T, Dims> x{};
    for (int e = 0; e < static_cast<int>(Dims); ++e)
      x[e] = e == d ? node(k, n, lo[d], hi[d]) : (lo[e] + hi[e]) / T(2);
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
    if (last != nullptr && (o == 0 || !(abs(values[(n - 1) * Outputs + o]) <= *last)))
      *last = abs(values[(n - 1) * Outputs + o]);
  }
  return true;
}

/// The difference between f and the box's series at x, the largest over outputs, or NaN where f
/// fails.
template <class T, int Outputs, int Capacity, int Dims, class F>
T difference_at(const chebyshev_box<T, Outputs, Capacity, Dims>& box, F& f,
                const std::array<T, std::size_t{Dims}>& x) {
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
template <class T, int Outputs, int Capacity, int Dims, class F>
T check_box(const chebyshev_box<T, Outputs, Capacity, Dims>& box, F& f, int checks,
            long& evaluations) {
  T worst = T(0);
  auto keep = [&worst](const T& d) {
    if (!(d <= worst)) worst = d;
  };
  for (int corner = 0; corner < (1 << Dims); ++corner) {
    bool repeated = false;  // a held variable has one side: its corners coincide
    std::array<T, Dims> x{};
    for (int d = 0; d < Dims; ++d) {
      const bool high = (corner >> d) & 1;
      repeated = repeated || (high && box.lo[d] == box.hi[d]);
      x[d] = high ? box.hi[d] : box.lo[d];
    }
    if (repeated) continue;
    ++evaluations;
    keep(difference_at(box, f, x));
  }
  static_assert(Dims <= 6, "the check's sequence has six multipliers");
  const long multipliers[6] = {40503, 49471, 37345, 52429, 44939, 34421};
  for (int k = 1; k <= checks; ++k) {
    std::array<T, Dims> x{};
    for (int d = 0; d < Dims; ++d)
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
/// too few); 1 for a held variable (lo == hi), and, where `fewest_nodes` is 1, for a variable
/// whose three-node sweep varies by less than the quarter (the series constant in it); 2, where
/// `fewest_nodes` is at most 2, for one whose three-node sweep's last coefficient is within the
/// quarter (the series linear in it: the checks say whether that holds); 0 where it
/// needs more than `most_nodes` (at most 64), f fails, or the sweeps would pass `budget`
/// evaluations. Adds the evaluations spent to `evaluations`.
template <class T, int Outputs, std::size_t Dims, class F>
int chebyshev_variable_nodes(const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, int d,
                             F&& f, const T& tolerance, long budget, long& evaluations,
                             int most_nodes = 64, int fewest_nodes = 3) {
  using std::log;
  if (lo[d] == hi[d]) return 1;
  const int* const begin = std::begin(chebyshev_detail::schedule);
  const int* const end = std::end(chebyshev_detail::schedule);
  const int* next = begin;
  int last_n = 0;
  T last_tail = T(0);
  while (next != end && *next <= most_nodes) {
    const int n = *next;
    T tail = T(0);
    if (evaluations + n > budget) return 0;
    evaluations += n;
    T sweep_curvature = T(0);  // |c_{n-1}|
    if (!chebyshev_detail::sweep_tail<T, Outputs>(lo, hi, d, n, f, tail, &sweep_curvature))
      return 0;
    // A quarter of the tolerance: the fit's error between the sweep's line and the box's corners
    // (the other variables' terms) is left the rest.
    const T target = tolerance / T(4);
    if (tail <= target) {
      // The line's whole variation, |c1| + |c2| of three nodes, within the target: one node
      // where the caller allows it (the series constant in the variable; its checks span the
      // range).
      const bool constant = fewest_nodes == 1 && n == 3;
      return constant ? 1 : n;
    }
    // Its curvature, |c2| of three nodes, within the target: two where the caller allows it (the
    // series linear in the variable).
    if (fewest_nodes <= 2 && n == 3 && sweep_curvature <= target) return 2;
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
template <class T, int Outputs, std::size_t Dims, class F>
chebyshev_box_report<T, static_cast<int>(Dims)> chebyshev_box_nodes(
    const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, F&& f, const T& tolerance,
    long budget, int most_nodes = 64, int fewest_nodes = 3) {
  chebyshev_box_report<T, static_cast<int>(Dims)> report;
  report.ok = true;
  for (int d = 0; d < static_cast<int>(Dims); ++d) {
    report.nodes[d] = chebyshev_variable_nodes<T, Outputs>(
        lo, hi, d, f, tolerance, budget, report.evaluations, most_nodes, fewest_nodes);
    if (report.nodes[d] == 0) report.ok = false;
  }
  return report;
}

/// Fits `box` to f on [lo, hi] with `nodes` (chebyshev_box_nodes') to `tolerance` (absolute,
/// every output): one fit, then f against the series at the box's corners and `checks` points
/// inside it, every difference within the tolerance; where one is not, every varying variable
/// takes the count of the schedule past a quarter more nodes and the box is fitted and checked
/// again (`attempts` fits in all, 3 unless said). Gives up (ok false) where f fails, a variable
/// would need more than 64 nodes, the box more than Capacity, or the evaluations would pass
/// `budget` (the caller's price for the table: f is the slow method).
template <class T, int Outputs, int Capacity, int Dims, class F>
chebyshev_box_report<T, Dims> chebyshev_box_fit_checked(
    chebyshev_box<T, Outputs, Capacity, Dims>& box, const std::array<T, std::size_t{Dims}>& lo,
    const std::array<T, std::size_t{Dims}>& hi, const std::array<int, std::size_t{Dims}>& nodes,
    F&& f, const T& tolerance, long budget, int checks = 16, int attempts = 3) {
  chebyshev_box_report<T, Dims> report;
  box.lo = lo;
  box.hi = hi;
  box.nodes = nodes;
  for (int attempt = 0; attempt < attempts; ++attempt) {
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
    for (int d = 0; d < Dims; ++d) {  // a quarter more nodes, at least one
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
template <class T, int Outputs, int Capacity, int Dims, class F>
chebyshev_box_report<T, Dims> chebyshev_box_build(chebyshev_box<T, Outputs, Capacity, Dims>& box,
                                                  const std::array<T, std::size_t{Dims}>& lo,
                                                  const std::array<T, std::size_t{Dims}>& hi, F&& f,
                                                  const T& tolerance, long budget,
                                                  int checks = 16) {
  const chebyshev_box_report<T, Dims> plan =
      chebyshev_box_nodes<T, Outputs>(lo, hi, f, tolerance, budget);
  if (!plan.ok) return plan;
  chebyshev_box_report<T, Dims> report = chebyshev_box_fit_checked(
      box, lo, hi, plan.nodes, f, tolerance, budget - plan.evaluations, checks);
  report.evaluations += plan.evaluations;
  return report;
}

}  // namespace conescan
