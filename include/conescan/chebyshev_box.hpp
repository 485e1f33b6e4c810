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
// says where it holds. A function may be told the points it is about to be asked for
// (chebyshev_detail::prefetching), which the scene's table computes on several threads.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>

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

/// Whether f may be told the points it is about to be asked for: a type that declares
/// `using prefetching = void;` and `prefetch(count, point_at)` (point_at(i), i in [0, count), the
/// points in the order f will be asked for them). Every function here that asks f for several
/// independent points tells it first, so that a caller can evaluate them together (the scene's
/// table runs the chain on them in parallel: src/simulation/physics_table.cpp); f's answers must
/// not depend on the order it computes them in. A plain callable is asked one point at a time.
template <class F, class = void>
struct prefetching : std::false_type {};
template <class F>
struct prefetching<F, std::void_t<typename F::prefetching>> : std::true_type {};

template <class F, class PointAt>
void prefetch(F& f, int count, const PointAt& point_at) {
  if constexpr (prefetching<std::remove_cv_t<std::remove_reference_t<F>>>::value)
    if (count > 1) f.prefetch(count, point_at);
}

/// The box's node at `flat` in the coefficients' order (the last variable fastest).
template <class T, int Outputs, int Capacity, int Dims>
std::array<T, std::size_t{Dims}> grid_point(const chebyshev_box<T, Outputs, Capacity, Dims>& box,
                                            int flat) noexcept {
  std::array<T, std::size_t{Dims}> x{};
  for (int d = Dims - 1; d >= 0; --d) {
    x[d] = node(flat % box.nodes[d], box.nodes[d], box.lo[d], box.hi[d]);
    flat /= box.nodes[d];
  }
  return x;
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
  const auto point_at = [&box](int flat) { return chebyshev_detail::grid_point(box, flat); };
  chebyshev_detail::prefetch(f, box.count(), point_at);
  for (int flat = 0; flat < box.count(); ++flat) {
    std::array<T, Outputs> out{};
    if (!f(point_at(flat), out)) return false;
    for (int o = 0; o < Outputs; ++o) {
      if (!is_finite(out[o])) return false;
      box.coefficients[flat * Outputs + o] = out[o];
    }
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

/// The node counts chebyshev_box_fit_checked steps through where a fit's checks fail.
inline constexpr int schedule[] = {3,  4,  5,  6,  7,  8,  10, 12, 14, 16,
                                   18, 21, 24, 28, 32, 37, 43, 50, 57, 64};

/// The k-th of n = N + 1 Chebyshev extrema on [lo, hi] (k = 0 at hi, N at lo; N even): the sine
/// form puts the middle (k = N / 2) exactly at (lo + hi) / 2 and keeps the points symmetric, and
/// the points of n are those of 2n - 1 at even k (a sweep's next count reuses its values).
template <class T>
T extremum(int k, int n, const T& lo, const T& hi) noexcept {
  using std::sin;
  const int N = n - 1;
  const T middle = (lo + hi) / T(2), half = (hi - lo) / T(2);
  if (2 * k == N) return middle;
  return middle + half * T(sin(pi<T>() * T(N - 2 * k) / T(2 * N)));
}

/// One variable's sweep through the box's middle at nested Chebyshev extrema (3, 5, 9, 17, ...
/// points): the values so far, one row of Outputs per point in extremum's order.
template <class T, int Outputs>
struct extrema_sweep {
  int n = 0;
  std::array<T, 65 * Outputs> values{};
  std::array<T, 65 * Outputs> coefficients{};  // |a_m| of each output, by transform_extrema

  /// Extends the sweep to `next` = 2n - 1 points (3 from none): the new points only, the middle's
  /// value from `middle` (every variable's sweep shares it). false where f fails or a value is
  /// not finite.
  template <std::size_t Dims, class F>
  bool extend(const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, int d, int next,
              const std::array<T, Outputs>& middle, F& f) {
    std::array<T, 65 * Outputs> old = values;
    const auto point_of = [&](int k) {
      std::array<T, Dims> x{};
      for (int e = 0; e < static_cast<int>(Dims); ++e)
        x[e] = e == d ? extremum(k, next, lo[d], hi[d]) : (lo[e] + hi[e]) / T(2);
      return x;
    };
    // The fresh points: the odd k once the sweep has values (the even ones are the last sweep's),
    // else (three points) the two ends, k = 0 and 2.
    prefetch(f, n > 0 ? next - n : 2, [&](int i) { return point_of(n > 0 ? 2 * i + 1 : 2 * i); });
    for (int k = 0; k < next; ++k) {
      std::array<T, Outputs> out{};
      if (n > 0 && k % 2 == 0) {
        for (int o = 0; o < Outputs; ++o) out[o] = old[(k / 2) * Outputs + o];
      } else if (2 * k == next - 1) {
        out = middle;
      } else {
        if (!f(point_of(k), out)) return false;
        for (int o = 0; o < Outputs; ++o)
          if (!is_finite(out[o])) return false;
      }
      for (int o = 0; o < Outputs; ++o) values[k * Outputs + o] = out[o];
    }
    n = next;
    transform_extrema();
    return true;
  }

  /// The interpolant's Chebyshev coefficients in absolute value (the discrete cosine transform of
  /// the first kind): a_m = (2 - [m = 0 or N]) / N sum'' f_k cos(pi m k / N), the sum's first and
  /// last terms halved.
  void transform_extrema() noexcept {
    using std::abs;
    using std::cos;
    const int N = n - 1;
    for (int o = 0; o < Outputs; ++o)
      for (int m = 0; m <= N; ++m) {
        T sum = T(0);
        for (int k = 0; k <= N; ++k) {
          const T term = values[k * Outputs + o] * T(cos(pi<T>() * T(m * k % (2 * N)) / T(N)));
          sum += (k == 0 || k == N) ? term / T(2) : term;
        }
        coefficients[m * Outputs + o] = abs(sum * T(m == 0 || m == N ? 1 : 2) / T(N));
      }
  }

  /// The sum of |a_k| from k = `from` on, the largest over outputs.
  T coefficient_sum(int from) const noexcept {
    T worst = T(0);
    for (int o = 0; o < Outputs; ++o) {
      T sum = T(0);
      for (int k = from; k < n; ++k) sum += coefficients[k * Outputs + o];
      if (!(sum <= worst)) worst = sum;
    }
    return worst;
  }
  /// The series' error left by m terms, estimated from the sweep's coefficients: the sum of |a_k|
  /// from k = m on, and at least the last two (one small coefficient may be a symmetry's zero):
  /// so m <= n - 2 where the estimate is to mean anything.
  T tail(int m) const noexcept { return coefficient_sum(std::min(m, n - 2)); }
};

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
/// ratios' fractional parts, modulo 2^16), exact in every scalar. The corners are those of the
/// variables with more than one node; a one-node variable over a range (the series constant in
/// it, its sweep end to end within a quarter of the tolerance) is at its low end on the corners
/// with an even number of high ends and at its high end on the others: both its ends are checked
/// without doubling the corners (an ellipsoid's piece has up to four such variables: 4 corners
/// instead of 64). A box held in every variable is one point, its one node: compared there once.
/// The worst difference and the evaluations spent; NaN (or the infinite difference) at the first
/// point where f fails or is not finite, the points after it not compared.
template <class T, int Outputs, int Capacity, int Dims, class F>
T check_box(const chebyshev_box<T, Outputs, Capacity, Dims>& box, F& f, int checks,
            long& evaluations) {
  std::array<int, Dims> spanned{};  // the variables with more than one node
  int span_count = 0;
  bool ranged_one_node = false, one_point = true;
  for (int d = 0; d < Dims; ++d) {
    if (box.nodes[d] > 1) spanned[span_count++] = d;
    ranged_one_node = ranged_one_node || (box.nodes[d] == 1 && !(box.lo[d] == box.hi[d]));
    one_point = one_point && box.lo[d] == box.hi[d];
  }
  const int corners = std::max(1 << span_count, ranged_one_node ? 2 : 1);
  static_assert(Dims <= 6, "the check's sequence has six multipliers");
  const long multipliers[6] = {40503, 49471, 37345, 52429, 44939, 34421};
  // Point i: corner i, then the sequence's k = i - corners + 1.
  const auto point_at = [&](int i) {
    std::array<T, Dims> x{};
    if (i >= corners) {
      const long k = i - corners + 1;
      for (int d = 0; d < Dims; ++d)
        x[d] = box.lo[d] + (box.hi[d] - box.lo[d]) * T((k * multipliers[d]) % 65536) / T(65536);
      return x;
    }
    bool odd = false;
    for (int bit = i; bit != 0; bit &= bit - 1) odd = !odd;
    for (int d = 0; d < Dims; ++d) x[d] = odd ? box.hi[d] : box.lo[d];
    for (int j = 0; j < span_count; ++j)
      x[spanned[j]] = (i >> j) & 1 ? box.hi[spanned[j]] : box.lo[spanned[j]];
    return x;
  };
  const int count = one_point ? corners : corners + checks;
  prefetch(f, count, point_at);
  T worst = T(0);
  for (int i = 0; i < count; ++i) {
    ++evaluations;
    const T d = difference_at(box, f, point_at(i));
    if (!is_finite(d))
      return d;  // f failed: the box is not checked (a later point must not hide it)
    if (d > worst) worst = d;
  }
  return worst;
}

}  // namespace chebyshev_detail

/// The nodes variable d of f on [lo, hi] needs for `tolerance` (absolute, every output): sweeps
/// through the box's middle at nested Chebyshev extrema (3, 5, 9, 17, 33, 65 points, each reusing
/// the last one's values; `middle` is f at the box's middle), until some m <= `most_nodes` leaves
/// a series tail (chebyshev_detail::extrema_sweep::tail) within a quarter of the tolerance: the
/// least such m, at least 3 and at most n - 2 of an n-point sweep (so at most 63), the sweeps
/// stopping at the first n with n - 2 >= most_nodes (the fit is checked after:
/// chebyshev_box_fit_checked).
/// 1 for a held variable (lo == hi), and, where `fewest_nodes` is 1, for a variable whose
/// three-point sweep varies by less than the quarter (the series constant in it); 2, where
/// `fewest_nodes` is at most 2, for one whose three-point sweep's curvature is within the
/// quarter (the series linear in it: the checks say whether that holds); 0 where it needs more
/// than `most_nodes`, f fails, or the sweeps would pass `budget` evaluations. Adds the
/// evaluations spent to `evaluations`. A variable that needs n nodes costs at most 2n + 1
/// evaluations (the schedule 3, 4, 5, 6, 7, 8, 10, ... this replaced re-evaluated every point at
/// each count: an orbit's ellipsoid table spent 55 % of its evaluations in sweeps).
template <class T, int Outputs, std::size_t Dims, class F>
int chebyshev_variable_nodes(const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, int d,
                             const std::array<T, Outputs>& middle, F&& f, const T& tolerance,
                             long budget, long& evaluations, int most_nodes = 64,
                             int fewest_nodes = 3) {
  if (lo[d] == hi[d]) return 1;
  // A quarter of the tolerance: the fit's error between the sweep's line and the box's corners
  // (the other variables' terms) is left the rest.
  const T target = tolerance / T(4);
  chebyshev_detail::extrema_sweep<T, Outputs> sweep;
  for (int n = 3; n <= 65; n = 2 * n - 1) {
    const int fresh = sweep.n == 0 ? n - 1 : n - sweep.n;  // the middle is known
    if (evaluations + fresh > budget) return 0;
    evaluations += fresh;
    if (!sweep.extend(lo, hi, d, n, middle, f)) return 0;
    if (n == 3) {
      // The line's whole variation (|a1| + |a2|) within the target: one node where the caller
      // allows it (its checks span the range); its curvature (|a2|): two.
      if (fewest_nodes == 1 && sweep.coefficient_sum(1) <= target) return 1;
      if (fewest_nodes <= 2 && sweep.coefficient_sum(2) <= target) return 2;
    }
    for (int m = 3; m <= std::min(n - 2, most_nodes); ++m)
      if (sweep.tail(m) <= target) return m;
    if (n - 2 >= most_nodes) return 0;  // the next sweep would pick no count the caller allows
  }
  return 0;
}

/// f at the box's middle, the point every variable's sweep shares (one evaluation, added to
/// `evaluations`); false where f fails there, a value is not finite, or the budget is spent.
template <class T, std::size_t Outputs, std::size_t Dims, class F>
bool chebyshev_box_middle(const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, F& f,
                          long budget, long& evaluations, std::array<T, Outputs>& middle) {
  if (evaluations + 1 > budget) return false;
  ++evaluations;
  std::array<T, Dims> x{};
  for (std::size_t d = 0; d < Dims; ++d) x[d] = (lo[d] + hi[d]) / T(2);
  if (!f(x, middle)) return false;
  for (const T& value : middle)
    if (!is_finite(value)) return false;
  return true;
}

/// chebyshev_variable_nodes of each variable, `first` first (the one likeliest to fail: a plan
/// stops at its first variable that fails, ok false).
template <class T, int Outputs, std::size_t Dims, class F>
chebyshev_box_report<T, static_cast<int>(Dims)> chebyshev_box_nodes(
    const std::array<T, Dims>& lo, const std::array<T, Dims>& hi, F&& f, const T& tolerance,
    long budget, int most_nodes = 64, int fewest_nodes = 3, int first = 0) {
  chebyshev_box_report<T, static_cast<int>(Dims)> report;
  bool varies = false;
  for (std::size_t d = 0; d < Dims; ++d) varies = varies || !(lo[d] == hi[d]);
  std::array<T, Outputs> middle{};
  if (varies && !chebyshev_box_middle(lo, hi, f, budget, report.evaluations, middle)) return report;
  for (int k = 0; k < static_cast<int>(Dims); ++k) {
    const int d = k == 0 ? first : (k <= first ? k - 1 : k);
    report.nodes[d] = chebyshev_variable_nodes<T, Outputs>(
        lo, hi, d, middle, f, tolerance, budget, report.evaluations, most_nodes, fewest_nodes);
    if (report.nodes[d] == 0) return report;
  }
  report.ok = true;
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
