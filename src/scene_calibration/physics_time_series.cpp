#include "scene_calibration/physics_time_series.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace conescan::calibration {

/// Nodes x in [-1, 1] of a piece's time span and their barycentric weights.
struct node_set {
  std::vector<double> x, weight;
};

/// A stretch of rows [first, end): served by the chain's values at its nodes through
/// barycentric weights, or left to the chain. The shifts are interpolated through every node,
/// their gradients (a build with gradients) through every other one: a Jet's chain costs 5 to 20
/// times a double's, and the gradients need not the shifts' 1e-7 deg (MODEL §11's fit asks them
/// for its steps and its 1 sigma: 1e-4 of their size moves neither by more than 1e-4 of itself).
struct physics_time_series::piece {
  std::size_t first = 0, end = 0;
  bool served = false;
  double middle_s = 0, half_span_s = 1;
  node_set values_at, gradients_at;
  std::vector<std::array<double, 2>> shift;
  std::vector<std::array<series_inputs, 2>> gradient;
  double chord_lo_rad = 0, chord_hi_rad = 0;  ///< the geometric chords its nodes and checks saw
};

struct physics_time_series::block {
  std::mutex lock;
  std::size_t first = 0, end = 0;
  bool built = false;
  series_mask gradient = 0;  ///< the inputs whose gradients it carries
  series_inputs inputs{};
  std::vector<piece> pieces;  ///< in order of rows, covering [first, end)
};

namespace {

/// A row's chord may pass those the piece saw by this much (rad, 0.057 deg) and be served: a
/// chord's extremum between two nodes passes them by far less. Not guarded: a status the chord
/// alone decides (a field as wide as the chord, a lag's memory longer than the sky's arc) whose
/// threshold lies within the margin of a chord the chain found ok (docs/DECISIONS.md).
constexpr double chord_margin_rad = 1e-3;

bool same_inputs(const series_inputs& a, const series_inputs& b) noexcept {
  return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;  // NaN (an absent input) equals itself
}

/// Barycentric weights of arbitrary distinct nodes x (the second form's: 1 / prod (x_j - x_k)).
std::vector<double> barycentric_weights(const std::vector<double>& x) {
  std::vector<double> w(x.size(), 1.0);
  for (std::size_t j = 0; j < x.size(); ++j)
    for (std::size_t k = 0; k < x.size(); ++k)
      if (k != j) w[j] /= x[j] - x[k];
  return w;
}

}  // namespace

bool series_times_usable(const std::vector<double>& times_s) noexcept {
  for (std::size_t i = 1; i < times_s.size(); ++i)
    if (!(times_s[i] > times_s[i - 1])) return false;
  return !times_s.empty() && std::isfinite(times_s.front()) && std::isfinite(times_s.back());
}

physics_time_series::physics_time_series(std::vector<double> times_s,
                                         physics_time_series_settings settings)
    : times_s_(std::move(times_s)), settings_(settings) {
  std::size_t first = 0;
  while (first < times_s_.size()) {
    std::size_t end = first + 1;
    while (end < times_s_.size() && times_s_[end] - times_s_[first] <= settings_.block_s) ++end;
    // A last stretch shorter than half a block joins this one: a piece too short to pay would
    // leave its rows to the chain.
    if (times_s_.back() - times_s_[first] <= 1.5 * settings_.block_s) end = times_s_.size();
    auto b = std::make_unique<block>();
    b->first = first;
    b->end = end;
    blocks_.push_back(std::move(b));
    block_first_.push_back(first);
    first = end;
  }
}

physics_time_series::~physics_time_series() = default;

namespace {

template <std::size_t N>
void add_scaled(std::array<double, N>& sum, double c, const std::array<double, N>& v) {
  for (std::size_t i = 0; i < N; ++i) sum[i] += c * v[i];
}
template <std::size_t N, std::size_t M>
void add_scaled(std::array<std::array<double, M>, N>& sum, double c,
                const std::array<std::array<double, M>, N>& v) {
  for (std::size_t i = 0; i < N; ++i) add_scaled(sum[i], c, v[i]);
}

/// The barycentric interpolant of values v at nodes s, at x_at (the node's value on a node).
template <class V>
V barycentric(const node_set& s, const std::vector<V>& v, double x_at) {
  V sum{};
  double denominator = 0;
  for (std::size_t j = 0; j < s.x.size(); ++j) {
    if (x_at == s.x[j]) return v[j];
    const double c = s.weight[j] / (x_at - s.x[j]);
    denominator += c;
    add_scaled(sum, c, v[j]);
  }
  V out{};
  add_scaled(out, 1 / denominator, sum);
  return out;
}

/// The nearest row to t_s among [first, end) of times.
std::size_t nearest_row(const std::vector<double>& times, std::size_t first, std::size_t end,
                        double t_s) {
  const auto begin = times.begin() + static_cast<std::ptrdiff_t>(first);
  const auto stop = times.begin() + static_cast<std::ptrdiff_t>(end);
  auto at = std::lower_bound(begin, stop, t_s);
  if (at == stop) return end - 1;
  if (at != begin && t_s - *(at - 1) < *at - t_s) --at;
  return static_cast<std::size_t>(at - times.begin());
}

/// True when the chain's sample at a check agrees with the interpolant: shifts within the
/// tolerance, each gradient within its share of the largest size it takes at the nodes.
bool agrees(const series_sample& chain, const series_sample& interpolated,
            const std::vector<std::array<series_inputs, 2>>& nodes, bool gradient,
            const physics_time_series_settings& settings) {
  for (std::size_t c = 0; c < 2; ++c) {
    if (!(std::abs(chain.shift[c] - interpolated.shift[c]) <= settings.tolerance_rad)) return false;
    if (!gradient) continue;
    for (std::size_t i = 0; i < series_input_count; ++i) {
      double size = 0;
      for (const auto& n : nodes) size = std::max(size, std::abs(n[c][i]));
      if (!(std::abs(chain.gradient[c][i] - interpolated.gradient[c][i]) <=
            settings.gradient_tolerance * size))
        return false;
    }
  }
  return true;
}

}  // namespace

bool physics_time_series::shift_at(std::size_t row, const series_inputs& inputs,
                                   series_mask gradient, double chord_rad,
                                   const series_evaluator& evaluate, series_sample& out) const {
  const auto k = static_cast<std::size_t>(
      std::upper_bound(block_first_.begin(), block_first_.end(), row) - block_first_.begin() - 1);
  block& b = *blocks_[k];
  const std::lock_guard<std::mutex> guard(b.lock);
  // At the same inputs a block asked for other gradients is built with both sets, so that
  // requests alternating between two sets do not rebuild it each time.
  const bool same = b.built && same_inputs(b.inputs, inputs);
  if (!same || (gradient & ~b.gradient) != 0)
    build(b, inputs, same ? series_mask(gradient | b.gradient) : gradient, evaluate);
  const auto p = std::upper_bound(b.pieces.begin(), b.pieces.end(), row,
                                  [](std::size_t r, const piece& q) { return r < q.first; }) -
                 1;
  if (!p->served || !(chord_rad >= p->chord_lo_rad - chord_margin_rad) ||
      !(chord_rad <= p->chord_hi_rad + chord_margin_rad))
    return false;
  interpolate(*p, times_s_[row], b.gradient != 0, out);
  served_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

void physics_time_series::build(block& b, const series_inputs& inputs, series_mask gradient,
                                const series_evaluator& evaluate) const {
  b.pieces.clear();
  b.inputs = inputs;
  b.gradient = gradient;
  build_piece(b, b.first, b.end, inputs, gradient, evaluate);
  b.built = true;
}

void physics_time_series::interpolate(const piece& p, double t_s, bool gradient,
                                      series_sample& out) {
  const double x = (t_s - p.middle_s) / p.half_span_s;
  out.ok = true;
  out.shift = barycentric(p.values_at, p.shift, x);
  if (gradient) out.gradient = barycentric(p.gradients_at, p.gradient, x);
}

void physics_time_series::build_piece(block& b, std::size_t first, std::size_t end,
                                      const series_inputs& inputs, series_mask gradient,
                                      const series_evaluator& evaluate) const {
  const auto least = static_cast<std::size_t>(2 * (settings_.nodes + settings_.checks));
  piece p;
  p.first = first;
  p.end = end;
  if (end - first < least) {
    b.pieces.push_back(std::move(p));  // too short to pay: the chain's
    return;
  }
  p.middle_s = (times_s_[first] + times_s_[end - 1]) / 2;
  p.half_span_s = (times_s_[end - 1] - times_s_[first]) / 2;
  const std::vector<node_row> rows = node_rows(p);
  const bool fits = rows.size() >= 4 && take_nodes(p, rows, inputs, gradient, evaluate) &&
                    checks_pass(p, rows, inputs, gradient, evaluate);
  if (fits || end - first < 2 * least) {
    p.served = fits;
    b.pieces.push_back(std::move(p));
    return;
  }
  const std::size_t middle =
      nearest_row(times_s_, first, end, (times_s_[first] + times_s_[end - 1]) / 2);
  build_piece(b, first, middle, inputs, gradient, evaluate);
  build_piece(b, middle, end, inputs, gradient, evaluate);
}

std::vector<physics_time_series::node_row> physics_time_series::node_rows(const piece& p) const {
  // Chebyshev-Lobatto points of the piece's span, each snapped to its nearest row; every other
  // one (from the first) carries the gradients.
  const int n = settings_.nodes;
  std::vector<node_row> rows;
  for (int j = 0; j < n; ++j) {
    const double t_s = p.middle_s - p.half_span_s * std::cos(std::numbers::pi * j / (n - 1));
    const std::size_t r = nearest_row(times_s_, p.first, p.end, t_s);
    if (!rows.empty() && r == rows.back().row)
      rows.back().gradient |= j % 2 == 0;
    else
      rows.push_back({r, j % 2 == 0});
  }
  return rows;
}

bool physics_time_series::take_nodes(piece& p, const std::vector<node_row>& rows,
                                     const series_inputs& inputs, series_mask gradient,
                                     const series_evaluator& evaluate) const {
  for (const node_row& node : rows) {
    ++evaluations_;
    const series_sample s = evaluate(node.row, inputs, node.gradient ? gradient : series_mask{0});
    if (!s.ok) return false;
    const double x = (times_s_[node.row] - p.middle_s) / p.half_span_s;
    p.values_at.x.push_back(x);
    p.shift.push_back(s.shift);
    if (gradient != 0 && node.gradient) {
      p.gradients_at.x.push_back(x);
      p.gradient.push_back(s.gradient);
    }
    p.chord_lo_rad = p.shift.size() == 1 ? s.chord_rad : std::min(p.chord_lo_rad, s.chord_rad);
    p.chord_hi_rad = p.shift.size() == 1 ? s.chord_rad : std::max(p.chord_hi_rad, s.chord_rad);
  }
  p.values_at.weight = barycentric_weights(p.values_at.x);
  p.gradients_at.weight = barycentric_weights(p.gradients_at.x);
  return true;
}

bool physics_time_series::checks_pass(piece& p, const std::vector<node_row>& rows,
                                      const series_inputs& inputs, series_mask gradient,
                                      const series_evaluator& evaluate) const {
  // Rows halfway between nodes, in gaps spread over the piece: its first and last gaps, where
  // the snapped nodes' interpolant is least sure, and between them.
  const std::size_t gaps = rows.size() - 1;
  const auto checks = static_cast<std::size_t>(settings_.checks);
  for (std::size_t c = 0; c < checks; ++c) {
    const std::size_t g = checks == 1 ? gaps / 2 : c * (gaps - 1) / (checks - 1);
    const std::size_t r = nearest_row(times_s_, p.first, p.end,
                                      (times_s_[rows[g].row] + times_s_[rows[g + 1].row]) / 2);
    if (r == rows[g].row || r == rows[g + 1].row) continue;  // no row between these two nodes
    ++evaluations_;
    const series_sample chain = evaluate(r, inputs, gradient);
    if (!chain.ok) return false;
    series_sample interpolated;
    interpolate(p, times_s_[r], gradient != 0, interpolated);
    if (!agrees(chain, interpolated, p.gradient, gradient != 0, settings_)) return false;
    p.chord_lo_rad = std::min(p.chord_lo_rad, chain.chord_rad);
    p.chord_hi_rad = std::max(p.chord_hi_rad, chain.chord_rad);
  }
  return true;
}

}  // namespace conescan::calibration
