#include "simulation/physics_table.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>

#include "conescan/earth_disk.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/sensor_physics/height.hpp"
#include "text/parallel_parts.hpp"

namespace conescan::scene {

template <int Dims>
void basic_physics_table_range<Dims>::add(const std::array<double, Dims>& x) noexcept {
  for (int d = 0; d < Dims; ++d) {
    lo[d] = empty ? x[d] : std::min(lo[d], x[d]);
    hi[d] = empty ? x[d] : std::max(hi[d], x[d]);
  }
  empty = false;
}
template struct basic_physics_table_range<3>;
template struct basic_physics_table_range<6>;

template <int Dims>
physics_table_cells<Dims>::physics_table_cells(const basic_physics_table_range<Dims>& range,
                                               int split_variable, int count)
    : split(split_variable), lo(range.lo[split_variable]) {
  const double span = range.hi[split_variable] - range.lo[split_variable];
  if (!(span > 0)) count = 1;
  width = span > 0 ? span / count : 0.0;
  cells.resize(static_cast<std::size_t>(count));
  rows.assign(static_cast<std::size_t>(count), 0);
}

namespace {

// The cell of the value x among `count` cells of `width` from lo (one cell where width is 0), or
// -1 outside them. The range's top belongs to the last cell, and so does a value past it by
// rounding.
int cell_index(double x, double lo, double width, int count) {
  if (width == 0) return x == lo ? 0 : -1;
  const double place = (x - lo) / width;
  if (!(place >= 0 && place <= count * (1 + 1e-12))) return -1;
  return std::min(count - 1, static_cast<int>(place));
}

}  // namespace

template <int Dims>
int physics_table_cells<Dims>::cell_of(const std::array<double, Dims>& x) const noexcept {
  return cell_index(x[split], lo, width, static_cast<int>(cells.size()));
}

template <int Dims>
void physics_table_cells<Dims>::add(const std::array<double, Dims>& x, long count) noexcept {
  for (double v : x)
    if (!std::isfinite(v)) return;  // a row without a surface: the chain's
  const int c = cell_of(x);
  if (c < 0) return;
  cells[static_cast<std::size_t>(c)].add(x);
  rows[static_cast<std::size_t>(c)] += count;
}

template <int Dims>
double physics_table_cells<Dims>::middle_of(int cell) const noexcept {
  const basic_physics_table_range<Dims>& box = cells[static_cast<std::size_t>(cell)];
  return (box.lo[split] + box.hi[split]) / 2;
}

// Each cell's slopes: the line through the middles of the nearest cells with rows either side (or
// the cell's own where one side has none). Where a variable does not follow the split one (the
// Sun's declination, from orbits hours apart) the slope is noise, and rows_at keeps the box.
template <int Dims>
void physics_table_cells<Dims>::fit_slopes() {
  const int count = static_cast<int>(cells.size());
  slopes.assign(cells.size(), std::array<double, Dims>{});
  along.assign(cells.size(), basic_physics_table_range<Dims>{});
  const auto nearest = [&](int c, int step) {
    for (int n = c + step; n >= 0 && n < count; n += step)
      if (!cells[static_cast<std::size_t>(n)].empty) return n;
    return c;
  };
  for (int c = 0; c < count; ++c) {
    if (cells[static_cast<std::size_t>(c)].empty) continue;
    const int before = nearest(c, -1), after = nearest(c, 1);
    const double run = middle_of(after) - middle_of(before);
    if (!(run > 0)) continue;
    const basic_physics_table_range<Dims>& a = cells[static_cast<std::size_t>(before)];
    const basic_physics_table_range<Dims>& b = cells[static_cast<std::size_t>(after)];
    for (int d = 0; d < Dims; ++d)
      if (d != split)
        slopes[static_cast<std::size_t>(c)][d] =
            ((b.lo[d] + b.hi[d]) - (a.lo[d] + a.hi[d])) / 2 / run;
  }
}

template <int Dims>
void physics_table_cells<Dims>::add_along(const std::array<double, Dims>& x) noexcept {
  for (double v : x)
    if (!std::isfinite(v)) return;
  if (slopes.empty()) fit_slopes();
  const int c = cell_of(x);
  if (c < 0 || cells[static_cast<std::size_t>(c)].empty) return;
  const std::array<double, Dims>& slope = slopes[static_cast<std::size_t>(c)];
  std::array<double, Dims> y = x;
  for (int d = 0; d < Dims; ++d)
    if (d != split) y[d] = x[d] - slope[d] * (x[split] - middle_of(c));
  along[static_cast<std::size_t>(c)].add(y);
}

template <int Dims>
basic_physics_table_range<Dims> physics_table_cells<Dims>::rows_at(int cell,
                                                                   double at) const noexcept {
  const std::size_t c = static_cast<std::size_t>(cell);
  basic_physics_table_range<Dims> box = cells[c];
  box.lo[split] = box.hi[split] = at;
  if (along.empty() || along[c].empty) return box;
  for (int d = 0; d < Dims; ++d) {
    // The rows along the slope where they spread less about it than the box holds them.
    if (d == split || along[c].hi[d] - along[c].lo[d] > cells[c].hi[d] - cells[c].lo[d]) continue;
    const double carried = slopes[c][d] * (at - middle_of(cell));
    box.lo[d] = along[c].lo[d] + carried;
    box.hi[d] = along[c].hi[d] + carried;
  }
  return box;
}

template struct physics_table_cells<6>;

namespace {

// A row's geometric crossings and the chain's on `surface` (failed with the geometric status
// where that is not ok).
template <class Surface>
physics_table_row chain_row(const sensor_physics_head<double>& physics,
                            const sensor_head<double>& head, const crossings<double>& geometric,
                            const Surface& surface, double sin_sun_declination,
                            sensor_physics_workspace<double>& work) noexcept {
  physics_table_row row{geometric, {}};
  if (geometric.state != status::ok) {
    row.physics = crossings<double>::failed(geometric.state);
    return row;
  }
  row.physics = sensor_physics_crossings(physics, head.circle(), surface, sin_sun_declination,
                                         geometric, work);
  row.peak_part = work.peak_part;
  return row;
}

}  // namespace

physics_table_row physics_row_at(const sensor_physics_head<double>& physics,
                                 const sensor_head<double>& head, double radius_m,
                                 const physics_table_point& x,
                                 sensor_physics_workspace<double>& work) noexcept {
  const double sin_eta = std::sin(x[1]);
  const vec3<double> nadir(sin_eta * std::cos(x[2]), sin_eta * std::sin(x[2]), std::cos(x[1]));
  const disk_trig<double> disk = disk_trig_of(radius_m, x[0]);
  // The polar axis serves only the season term, which a table's scene has not: any unit vector.
  return chain_row(physics, head, head.scan_crossings(nadir, disk),
                   sphere_surface_of(nadir, disk, radius_m, nadir), 0.0, work);
}

namespace {

// The table's first variable: the distance to the horizon, sqrt(r^2 - R^2), in which the shifts
// are smoother than in r itself (a third fewer nodes over the paper's ellipse, measured); NaN
// inside the sphere.
double horizon_distance_m(double r_m, double radius_m) {
  return std::sqrt((r_m - radius_m) * (r_m + radius_m));
}

// The chain's rows at the points a build asks for, row_at(x, workspace). Where the build says
// which points it is about to ask for (chebyshev_detail::prefetching: a sweep's fresh points, a
// piece's nodes, its checks), they are computed together on up to `threads` threads, each with its
// own workspace, and handed out as the build asks for them; any other point is computed when
// asked. A row is a function of its point alone (the chain's workspace carries nothing from one
// row to the next, as the fit's threads rely on), so the build asks for the same points, gets the
// same values and makes the same table on any number of threads: only its wall time changes.
template <int Dims, class RowAt>
class prefetched_rows {
 public:
  using point = std::array<double, Dims>;

  prefetched_rows(RowAt row_at, int threads) : row_at_(std::move(row_at)), threads_(threads) {
    work_.push_back(std::make_unique<sensor_physics_workspace<double>>());
  }

  physics_table_row at(const point& x) {
    const auto ready = ready_.find(x);
    if (ready == ready_.end()) return row_at_(x, *work_.front());
    const physics_table_row row = ready->second;
    ready_.erase(ready);
    return row;
  }

  template <class PointAt>
  void prefetch(int count, const PointAt& point_at) {
    if (threads_ < 2) return;
    std::vector<point> points;
    for (int i = 0; i < count; ++i) {
      const point x = point_at(i);
      const bool finite =
          std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
      if (finite && ready_.count(x) == 0 &&
          std::find(points.begin(), points.end(), x) == points.end())
        points.push_back(x);
    }
    if (points.size() < 2) return;
    const std::size_t parts = text::parallel_part_count(points.size(), threads_);
    while (work_.size() < parts)
      work_.push_back(std::make_unique<sensor_physics_workspace<double>>());
    std::vector<physics_table_row> rows(points.size());
    // Part p runs on one thread at a time, with workspace p.
    text::parallel_parts(points.size(), threads_, parts,
                         [&](std::size_t begin, std::size_t end, std::size_t part) {
                           for (std::size_t i = begin; i < end; ++i)
                             rows[i] = row_at_(points[i], *work_[part]);
                         });
    for (std::size_t i = 0; i < points.size(); ++i) ready_.emplace(points[i], rows[i]);
  }

 private:
  RowAt row_at_;
  int threads_;
  std::vector<std::unique_ptr<sensor_physics_workspace<double>>> work_;  // front: the build's own
  std::map<point, physics_table_row> ready_;
};

// The chain at a point of the table's box, as simulation::physics_crossings runs it on a row
// there (`rows` maps the table's variables to the row): the two crossings' shifts from the
// geometric ones, or false where either is not ok. Records the geometric chords it saw (chord_lo,
// chord_hi): a row is trusted to the table only within them; and the part of the pulse that gave
// its peak (peak_part), where the build looks for kinks.
template <int Dims, class Rows>
struct chain_shifts {
  Rows* rows;
  double* chord_lo;
  double* chord_hi;
  int* peak_part;

  using prefetching = void;

  bool operator()(const std::array<double, Dims>& x, std::array<double, 2>& out) const {
    const physics_table_row row = rows->at(x);
    *peak_part = row.peak_part;
    if (row.physics.state != status::ok) return false;
    const crossings<double>& geometric = row.geometric;
    out = {row.physics.phi_in - geometric.phi_in, row.physics.phi_out - geometric.phi_out};
    *chord_lo = std::min(*chord_lo, geometric.chord());
    *chord_hi = std::max(*chord_hi, geometric.chord());
    return true;
  }
  template <class PointAt>
  void prefetch(int count, const PointAt& point_at) const {
    rows->prefetch(count, point_at);
  }
};

template <int Dims, class Rows>
chain_shifts<Dims, Rows> chain_shifts_of(Rows& rows, physics_series<Dims>& series) {
  series.chord_lo = 2 * pi<double>();
  series.chord_hi = 0;
  return {&rows, &series.chord_lo, &series.chord_hi, &series.last_peak_part};
}

// `shifts` asked at points mapped by `map` (a piece's offsets to the table's variables), with
// `seen(y, out, ok)` told of each answer; what the build is about to ask is passed on
// (chebyshev_detail::prefetching).
template <class Shifts, class Map, class Seen>
struct mapped_shifts {
  const Shifts* shifts;
  Map map;
  Seen seen;

  using prefetching = void;

  template <class Point>
  bool operator()(const Point& y, std::array<double, 2>& out) const {
    const bool ok = (*shifts)(map(y), out);
    seen(y, out, ok);
    return ok;
  }
  template <class PointAt>
  void prefetch(int count, const PointAt& point_at) const {
    chebyshev_detail::prefetch(*shifts, count, [&](int i) { return map(point_at(i)); });
  }
};

template <class Shifts, class Map, class Seen>
mapped_shifts<Shifts, Map, Seen> mapped_shifts_of(const Shifts& shifts, Map map, Seen seen) {
  return {&shifts, std::move(map), std::move(seen)};
}

// Where the nadir wanders (any variable but the first varies), the first is cut into pieces of
// about a dozen nodes each, so that a row's series has fewer terms (docs/SENSOR_PHYSICS.md, "The
// table").
template <std::size_t Dims>
int piece_count(const std::array<int, Dims>& whole_box_nodes) {
  int others = 1;
  for (std::size_t d = 1; d < Dims; ++d) others *= whole_box_nodes[d];
  if (others == 1) return 1;
  return std::clamp(
      (whole_box_nodes[0] + physics_table_piece_nodes - 1) / physics_table_piece_nodes, 1,
      physics_table_most_pieces);
}

}  // namespace

template <int Dims>
template <class Shifts>
bool physics_series<Dims>::build(const point& lo, const point& hi, const Shifts& shifts,
                                 long budget, long& evaluations) {
  const chebyshev_box_report<double, Dims> plan =
      chebyshev_box_nodes<double, 2>(lo, hi, shifts, physics_table_tolerance_rad, budget);
  evaluations = plan.evaluations;
  if (!plan.ok) return false;
  const int count = piece_count(plan.nodes);
  lo_m_ = lo[0];
  width_m_ = (hi[0] - lo[0]) / count;
  report.ok = true;
  for (int d = 0; d < Dims; ++d) report.nodes[d] = 0;
  for (int p = 0; p < count; ++p) {
    point piece_lo = lo, piece_hi = hi;
    piece_lo[0] = lo[0] + p * width_m_;
    piece_hi[0] = p + 1 == count ? hi[0] : lo[0] + (p + 1) * width_m_;
    if (!add_piece(piece_lo, piece_hi, count > 1 ? 0 : plan.nodes[0], plan.nodes, shifts, budget,
                   evaluations))
      return false;
  }
  report.evaluations = evaluations;
  return true;
}

template <int Dims>
template <class Shifts>
bool physics_series<Dims>::add_piece(const point& lo, const point& hi, int distance_nodes,
                                     const std::array<int, Dims>& angle_nodes, const Shifts& shifts,
                                     long budget, long& evaluations) {
  // The angles' nodes hold for every piece; the distance's are the piece's own (0: sweep it).
  std::array<int, Dims> nodes = angle_nodes;
  nodes[0] = distance_nodes;
  if (nodes[0] == 0) {
    std::array<double, 2> middle{};
    if (!chebyshev_box_middle(lo, hi, shifts, budget, evaluations, middle)) return false;
    nodes[0] = chebyshev_variable_nodes<double, 2>(
        lo, hi, 0, middle, shifts, physics_table_tolerance_rad, budget, evaluations);
  }
  if (nodes[0] == 0) return false;
  auto fitted = std::make_unique<box>();
  const chebyshev_box_report<double, Dims> built = chebyshev_box_fit_checked(
      *fitted, lo, hi, nodes, shifts, physics_table_tolerance_rad, budget - evaluations);
  evaluations += built.evaluations;
  if (!built.ok) return false;
  for (int d = 0; d < Dims; ++d) report.nodes[d] = std::max(report.nodes[d], built.nodes[d]);
  report.worst_check = std::max(report.worst_check, built.worst_check);
  pieces.push_back(std::move(fitted));
  return true;
}

// Eight first pieces (an eighth of an orbit each, where the split variable is the pole's
// azimuth); where the rows span less than a quarter of the split variable's period, ceil(8 span)
// (one or two), so that a short scene's pieces take the nodes they need (up to 15) where eight
// would each pay their own sweeps and checks. Measured on the paper's ellipse at 1 s with a 1.5
// deg square and the season term: 1024 rows 198 evaluations -> 87, 1200 rows 232 -> 92 (two
// pieces of 11 and 12 nodes); from 1500 rows (0.27 of the orbit) up to 4096, fewer first pieces
// cost 9-15 % more than eight, so eight there.
template <int Dims>
int first_pieces_of(const physics_table_cells<Dims>& cells) noexcept {
  const int count = static_cast<int>(cells.cells.size());
  const int most = std::min(count, physics_table_first_pieces);
  if (!(cells.split_period > 0)) return most;
  // The rows' span: the cells less their longest run without rows (a short arc that wraps
  // about the angle's cut has its gap inside the range; a day's orbits leave none).
  int gap = 0, run = 0;
  for (const auto& cell : cells.cells) {
    run = cell.empty ? run + 1 : 0;
    gap = std::max(gap, run);
  }
  const double periods = (count - gap) * cells.width / cells.split_period;
  if (!(periods < physics_table_short_span)) return most;
  return std::clamp(static_cast<int>(std::ceil(physics_table_first_pieces * periods)), 1, most);
}

template <int Dims>
template <class Shifts>
bool physics_series<Dims>::build_cells(const physics_table_cells<Dims>& cells, const Shifts& shifts,
                                       long budget, long& evaluations) {
  split_ = cells.split;
  cell_lo_ = cells.lo;
  cell_width_ = cells.width;
  piece_of_cell_.assign(cells.cells.size(), -1);
  report.ok = true;
  for (int d = 0; d < Dims; ++d) report.nodes[d] = 0;
  evaluations = 0;
  const int count = static_cast<int>(cells.cells.size());
  const int first_pieces = first_pieces_of(cells);
  for (int p = 0; p < first_pieces; ++p)
    add_cells(cells, count * p / first_pieces, count * (p + 1) / first_pieces, shifts, budget,
              evaluations);
  // Next to a cell the chain keeps, the nearest cell with rows on either side is the chain's too:
  // where the chain refuses a row (a status of its own) a piece's nodes and checks can all lie on
  // the side it accepts while a row of its edge cell does not (the benchmark's square field found
  // one such row near perigee).
  std::vector<int> kept(piece_of_cell_);
  for (int c = 0; c < count; ++c) {
    if (cells.cells[static_cast<std::size_t>(c)].empty || kept[c] >= 0) continue;
    for (int step : {-1, 1})
      for (int n = c + step; n >= 0 && n < count; n += step)
        if (!cells.cells[static_cast<std::size_t>(n)].empty) {
          piece_of_cell_[n] = -1;
          break;
        }
  }
  for (int c = 0; c < count; ++c)
    chain_cells += !cells.cells[static_cast<std::size_t>(c)].empty && piece_of_cell_[c] < 0;
  report.evaluations = evaluations;
  return !pieces.empty();
}

namespace {

// T_0(t) .. T_{Terms-1}(t).
template <std::size_t Terms>
std::array<double, Terms> chebyshev_values(double t) {
  std::array<double, Terms> values{};
  values[0] = 1;
  if (Terms > 1) values[1] = t;
  for (std::size_t k = 2; k < Terms; ++k) values[k] = 2 * t * values[k - 1] - values[k - 2];
  return values;
}

}  // namespace

template <int Dims>
typename physics_series<Dims>::point physics_series<Dims>::trend::values_at(
    double x_split) const noexcept {
  const std::array<double, terms> chebyshev = chebyshev_values<terms>(t_of(x_split));
  point values{};
  for (std::size_t d = 0; d < std::size_t{Dims}; ++d)
    for (std::size_t k = 0; k < terms; ++k) values[d] += coefficients[d][k] * chebyshev[k];
  return values;
}

template <int Dims>
typename physics_series<Dims>::point physics_series<Dims>::trend::apply(const point& x,
                                                                        int split) const noexcept {
  const point values = values_at(x[split]);
  point y = x;
  for (int d = 0; d < Dims; ++d)
    if (d != split) y[d] = x[d] - values[d];
  return y;
}

template <int Dims>
typename physics_series<Dims>::point physics_series<Dims>::trend::unapply(
    const point& y, int split) const noexcept {
  const point values = values_at(y[split]);
  point x = y;
  for (int d = 0; d < Dims; ++d)
    if (d != split) x[d] = y[d] + values[d];
  return x;
}

namespace {

// Solves the n x n system a c = b (n <= N) by Gaussian elimination with partial pivoting; false
// where it is singular to rounding (the caller then tries a lower degree).
template <std::size_t N>
bool solve_small(std::array<std::array<double, N>, N> a, std::array<double, N> b, int n,
                 std::array<double, N>& c) {
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
    if (!(std::abs(a[pivot][k]) > 1e-12 * std::abs(a[0][0]))) return false;
    std::swap(a[k], a[pivot]);
    std::swap(b[k], b[pivot]);
    for (int i = k + 1; i < n; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] -= f * a[k][j];
      b[i] -= f * b[k];
    }
  }
  c.fill(0.0);
  for (int k = n - 1; k >= 0; --k) {
    double sum = b[k];
    for (int j = k + 1; j < n; ++j) sum -= a[k][j] * c[j];
    c[k] = sum / a[k][k];
  }
  return true;
}

}  // namespace

// The polynomial in the split variable through the middles of the cells' boxes, for each other
// variable: the least-squares fit in Chebyshev polynomials of t in [-1, 1] of the highest degree up
// to 11 that the cells allow (two cells a coefficient) and the normal equations solve, cut to the
// least degree whose dropped coefficients sum to no more than the fit's largest offset from the
// middles (so that the offsets stay within twice it). A variable that follows the split one, as
// the distance does an orbit's pole azimuth, keeps the degree it needs; one that does not, as the
// Sun's declination over orbits hours apart, stays nearly constant: the whole fit through its
// scattered middles would only add wiggles the series must follow (12 nodes along the orbit
// where 6 to 8 had done, measured). A constant where the split variable is held in the cells.
template <int Dims>
void physics_series<Dims>::fit_trend(const physics_table_cells<Dims>& cells, int first, int last,
                                     trend& line) const {
  constexpr int terms = trend::terms;
  int n = 0;
  double lo = 0, hi = 0;
  for (int c = first; c < last; ++c) {
    if (cells.cells[static_cast<std::size_t>(c)].empty) continue;
    const double x = cells.middle_of(c);
    lo = n == 0 ? x : std::min(lo, x);
    hi = n == 0 ? x : std::max(hi, x);
    ++n;
  }
  line.middle = (lo + hi) / 2;
  line.half = (hi - lo) / 2;
  std::array<std::array<double, terms>, terms> normal{};
  std::array<std::array<double, terms>, std::size_t{Dims}> right{};
  for (int c = first; c < last; ++c) {
    const basic_physics_table_range<Dims>& cell = cells.cells[static_cast<std::size_t>(c)];
    if (cell.empty) continue;
    const std::array<double, terms> chebyshev =
        chebyshev_values<terms>(line.t_of(cells.middle_of(c)));
    for (int i = 0; i < terms; ++i) {
      for (int j = i; j < terms; ++j) normal[i][j] += chebyshev[i] * chebyshev[j];
      for (int d = 0; d < Dims; ++d)
        right[static_cast<std::size_t>(d)][i] += chebyshev[i] * (cell.lo[d] + cell.hi[d]) / 2;
    }
  }
  for (int i = 0; i < terms; ++i)
    for (int j = 0; j < i; ++j) normal[i][j] = normal[j][i];
  for (int d = 0; d < Dims; ++d) line.coefficients[static_cast<std::size_t>(d)].fill(0.0);
  if (n == 0) return;
  for (int d = 0; d < Dims; ++d)
    for (int degree = line.half > 0 ? std::min(terms - 1, (n - 1) / 2) : 0;
         d != split_ && degree >= 0; --degree)
      if (solve_small(normal, right[static_cast<std::size_t>(d)], degree + 1,
                      line.coefficients[static_cast<std::size_t>(d)]))
        break;
  cut_trend(cells, first, last, line);
}

// fit_trend's cut: each variable's largest offset from the cells' middles (one pass), then the
// least degree whose dropped coefficients sum to no more than it.
template <int Dims>
void physics_series<Dims>::cut_trend(const physics_table_cells<Dims>& cells, int first, int last,
                                     trend& line) const {
  point largest{};
  for (int c = first; c < last; ++c) {
    const basic_physics_table_range<Dims>& cell = cells.cells[static_cast<std::size_t>(c)];
    if (cell.empty) continue;
    const point values = line.values_at(cells.middle_of(c));
    for (int d = 0; d < Dims; ++d)
      largest[d] = std::max(largest[d], std::abs((cell.lo[d] + cell.hi[d]) / 2 - values[d]));
  }
  for (std::size_t d = 0; d < std::size_t{Dims}; ++d) {
    std::array<double, trend::terms>& a = line.coefficients[d];
    double dropped = 0;
    for (std::size_t k = trend::terms - 1; k >= 1; --k) {
      dropped += std::abs(a[k]);
      if (dropped > largest[d]) break;
      a[k] = 0;
    }
  }
}

// The piece's box in the offsets from `line`: each cell's rows at its split variable's ends and
// middle (cells.rows_at).
template <int Dims>
basic_physics_table_range<Dims> physics_series<Dims>::offset_box(
    const physics_table_cells<Dims>& cells, int first, int last, const trend& line) const {
  basic_physics_table_range<Dims> range;
  for (int c = first; c < last; ++c) {
    const basic_physics_table_range<Dims>& cell = cells.cells[static_cast<std::size_t>(c)];
    if (cell.empty) continue;
    // A cell of one row (most of a day's) is one place.
    const std::array<double, 3> places{cell.lo[split_], cells.middle_of(c), cell.hi[split_]};
    for (int p = 0; p < (places[0] == places[2] ? 1 : 3); ++p) {
      const basic_physics_table_range<Dims> rows =
          cells.rows_at(c, places[static_cast<std::size_t>(p)]);
      const point values = line.values_at(places[static_cast<std::size_t>(p)]);
      point lo = rows.lo, hi = rows.hi;
      for (int d = 0; d < Dims; ++d)
        if (d != split_) {
          lo[d] -= values[d];
          hi[d] -= values[d];
        }
      range.add(lo);
      range.add(hi);
    }
  }
  return range;
}

// The box the nodes are planned on: `range`, with a variable whose offsets span less than 1e-10 of
// its size (its trend's constant, at least 1: 1e-10 rad of an angle, 0.3 mm of a day's distance)
// held at its middle, so that it takes one node without a sweep. Such spans are the rounding of a
// held attitude's angles (1e-12 rad on a day's orbit) or a two-body orbit's distance about its
// trend; every node's sweep would cost two evaluations, a day's build on WGS84 some 150. The fit's
// checks still span the whole range (a one-node variable at its low end on half the corners).
template <int Dims>
basic_physics_table_range<Dims> physics_series<Dims>::plan_range(
    const basic_physics_table_range<Dims>& range, const trend& line) const {
  basic_physics_table_range<Dims> planned = range;
  for (int d = 0; d < Dims; ++d) {
    const double size = std::max(1.0, std::abs(line.coefficients[static_cast<std::size_t>(d)][0]));
    if (d != split_ && range.hi[d] - range.lo[d] <= physics_table_negligible_span * size)
      planned.lo[d] = planned.hi[d] = (range.lo[d] + range.hi[d]) / 2;
  }
  return planned;
}

template <int Dims>
template <class Shifts>
void physics_series<Dims>::add_cells(const physics_table_cells<Dims>& cells, int first, int last,
                                     const Shifts& shifts, long budget, long& evaluations) {
  // Rows the chain runs for fewer evaluations than the least a piece costs are left to it.
  const long piece_rows =
      std::accumulate(cells.rows.begin() + first, cells.rows.begin() + last, 0L);
  if (piece_rows < physics_table_least_piece_evaluations) return;
  trend line;
  fit_trend(cells, first, last, line);
  const basic_physics_table_range<Dims> range = offset_box(cells, first, last, line);
  if (range.empty) return;  // no row to serve
  // The shifts at offsets y: the chain at the row they stand for.
  const auto row_of = [&](const point& y) { return line.unapply(y, split_); };
  const auto offsets =
      mapped_shifts_of(shifts, row_of, [](const point&, const std::array<double, 2>&, bool) {});
  // The nodes: the piece's own sweeps (at most 15 a variable, the 17-point sweep's largest: a
  // piece that needs more is halved, which costs less than a longer sweep that fails at a kink (a
  // day's build on WGS84 with the season term and a field, measured with the earlier sweeps:
  // 17 558 evaluations with 32 nodes, 15 374 with 16); one where the shifts vary by less than a
  // quarter of the tolerance over its range).
  constexpr int most_nodes = 15;
  const basic_physics_table_range<Dims> planned_range = plan_range(range, line);
  // Every value the plan's sweeps read: checks of the piece's series for free, and (those of the
  // split variable's sweep, the plan's first, through the middle of the others) the places where
  // peak_switch_cells looks for a kink where the plan fails.
  std::vector<known_shift> known;
  const auto planning = mapped_shifts_of(
      shifts, row_of, [&](const point& y, const std::array<double, 2>& out, bool ok) {
        known.push_back({y, out, ok ? last_peak_part : -1, ok});
      });
  const chebyshev_box_report<double, Dims> plan = chebyshev_box_nodes<double, 2>(
      planned_range.lo, planned_range.hi, planning, physics_table_tolerance_rad,
      budget - evaluations, most_nodes, 1, split_);
  evaluations += plan.evaluations;
  // A plan the budget cut short, or a piece it cannot pay for: these rows, and every later
  // piece's, are the chain's; the pieces built so far serve theirs (what they cost is spent).
  if (!plan.ok && evaluations + 2 * most_nodes > budget) return;
  if (plan.ok) {
    const int total = std::accumulate(plan.nodes.begin(), plan.nodes.end(), 1, std::multiplies<>());
    if (evaluations + total + physics_table_spread_checks + (1 << Dims) > budget) return;
    std::unique_ptr<box> fitted =
        checked_piece(range, plan.nodes, offsets, known, budget, evaluations);
    if (fitted) return keep_piece(first, last, std::move(fitted), line);
  }
  // One cell, or halves that would cost more than their rows: the rows run the chain.
  if (last - first == 1 || piece_rows < 2 * physics_table_least_piece_evaluations) return;
  // A kink where the peak moves from one part of the pulse to another: the cells that hold it are
  // the chain's, and the pieces either side of them smooth (a day's build on WGS84 with the season
  // term halved one such piece eleven times, to cells of 2 and 3).
  int kink_lo = 0, kink_hi = 0;
  if (peak_switch_cells(first, last, range, offsets, split_sweep(known, planned_range), budget,
                        evaluations, kink_lo, kink_hi)) {
    add_cells(cells, first, kink_lo, shifts, budget, evaluations);
    add_cells(cells, kink_hi + 1, last, shifts, budget, evaluations);
    return;
  }
  const int middle = (first + last) / 2;
  add_cells(cells, first, middle, shifts, budget, evaluations);
  add_cells(cells, middle, last, shifts, budget, evaluations);
}

// The cells [first, last) served by the series `fitted` in offsets from `line`.
template <int Dims>
void physics_series<Dims>::keep_piece(int first, int last, std::unique_ptr<box> fitted,
                                      const trend& line) {
  for (int c = first; c < last; ++c) piece_of_cell_[c] = static_cast<int>(pieces.size());
  pieces.push_back(std::move(fitted));
  trends_.push_back(line);
}

// The places of the plan's sweep along the split variable (through the middle of the others) and
// the peak's part at each.
template <int Dims>
std::vector<std::pair<double, int>> physics_series<Dims>::split_sweep(
    const std::vector<known_shift>& known, const basic_physics_table_range<Dims>& planned) const {
  std::vector<std::pair<double, int>> places;
  for (const known_shift& k : known) {
    bool through_middle = true;
    for (int d = 0; d < Dims; ++d)
      through_middle =
          through_middle && (d == split_ || k.at[d] == (planned.lo[d] + planned.hi[d]) / 2);
    if (through_middle) places.emplace_back(k.at[split_], k.part);
  }
  return places;
}

// A piece's series at `nodes`, checked against the chain at its corners, at
// physics_table_spread_checks points spread over it, and at every place its plan read (`known`:
// the sweeps through its middle, some twenty values the chain has given already, most along the
// split variable, where the series is likeliest to err); null where a check is beyond the
// tolerance (the rows then go to smaller pieces or the chain). The report takes its nodes and
// worst check.
template <int Dims>
template <class Offsets>
std::unique_ptr<typename physics_series<Dims>::box> physics_series<Dims>::checked_piece(
    const basic_physics_table_range<Dims>& range, const std::array<int, Dims>& nodes,
    const Offsets& offsets, const std::vector<known_shift>& known, long budget, long& evaluations) {
  auto fitted = std::make_unique<box>();
  const chebyshev_box_report<double, Dims> built = chebyshev_box_fit_checked(
      *fitted, range.lo, range.hi, nodes, offsets, physics_table_tolerance_rad,
      budget - evaluations, physics_table_spread_checks, 1);
  evaluations += built.evaluations;
  if (!built.ok) return nullptr;
  double worst = built.worst_check;
  for (const known_shift& k : known) {
    if (!k.ok) continue;
    const std::array<double, 2> series = chebyshev_box_value(*fitted, k.at);
    worst = std::max({worst, std::abs(series[0] - k.shifts[0]), std::abs(series[1] - k.shifts[1])});
  }
  if (!(worst <= physics_table_tolerance_rad)) return nullptr;
  for (int d = 0; d < Dims; ++d) report.nodes[d] = std::max(report.nodes[d], built.nodes[d]);
  report.worst_check = std::max(report.worst_check, worst);
  return fitted;
}

// The places along the split variable through the piece's middle where the plan's sweep read the
// peak's part (17 where it failed for want of nodes), else nine evenly; then bisection between the
// first two whose peaks come from different parts, to adjacent cells.
template <int Dims>
template <class Offsets>
bool physics_series<Dims>::peak_switch_cells(int first, int last,
                                             const basic_physics_table_range<Dims>& range,
                                             const Offsets& offsets,
                                             std::vector<std::pair<double, int>> places,
                                             long budget, long& evaluations, int& lo, int& hi) {
  constexpr int fewest_places = 9;
  const int cell_count = static_cast<int>(piece_of_cell_.size());
  int bisections = 1;
  while ((1 << bisections) < (last - first)) ++bisections;
  const bool fresh = places.size() < std::size_t{fewest_places};
  if (evaluations + (fresh ? fewest_places : 0) + bisections > budget) return false;
  point y;
  for (int d = 0; d < Dims; ++d) y[d] = (range.lo[d] + range.hi[d]) / 2;
  const auto part_at = [&](double x) {
    y[split_] = x;
    std::array<double, 2> ignored{};
    ++evaluations;
    return offsets(y, ignored) ? last_peak_part : -1;
  };
  const double from = range.lo[split_], to = range.hi[split_];
  if (fresh) {
    places.clear();
    const auto place = [&](int i) { return from + (to - from) * i / (fewest_places - 1); };
    chebyshev_detail::prefetch(offsets, fewest_places, [&](int i) {
      point x = y;
      x[split_] = place(i);
      return x;
    });
    for (int i = 0; i < fewest_places; ++i) {
      const double x = place(i);
      places.emplace_back(x, part_at(x));
    }
  }
  std::sort(places.begin(), places.end());
  const auto cell_of = [&](double x) { return cell_index(x, cell_lo_, cell_width_, cell_count); };
  for (std::size_t i = 1; i < places.size(); ++i) {
    if (places[i - 1].second < 0 || places[i].second < 0) return false;
    if (places[i].second == places[i - 1].second) continue;
    double a = places[i - 1].first, b = places[i].first;
    for (int step = 0; step < bisections && cell_of(b) - cell_of(a) > 1; ++step) {
      const double m = (a + b) / 2;
      const int part = part_at(m);
      if (part < 0) return false;
      (part == places[i - 1].second ? a : b) = m;
    }
    lo = std::max(first, cell_of(a));
    hi = std::min(last - 1, cell_of(b));
    return cell_of(a) >= 0 && hi - lo <= 1 && lo <= hi;
  }
  return false;
}

template <int Dims>
bool physics_series<Dims>::shift_at(const point& at, double chord,
                                    std::array<double, 2>& shift) const noexcept {
  if (split_ >= 0) return cell_shift_at(at, chord, shift);
  const double place = width_m_ > 0 ? (at[0] - lo_m_) / width_m_ : 0.0;
  if (!(place >= 0)) return false;  // below the box, or NaN
  const std::size_t piece = std::min(pieces.size() - 1, static_cast<std::size_t>(place));
  // A held variable is the same double on every row (a constant attitude): no slack needed
  // beyond rounding.
  const box& fitted = *pieces[piece];
  if (!fitted.contains(at, 1e-12)) return false;
  // At a chord the build never saw the row is the chain's. Every chord it saw passed the chain's
  // own checks on the chord (physics_detail::row_status: the field narrower than the chord, the
  // lag's memory within the sky's arc), so a chord they refuse lies outside these too.
  if (!(chord >= chord_lo && chord <= chord_hi)) return false;
  shift = chebyshev_box_value(fitted, at);
  return true;
}

template <int Dims>
bool physics_series<Dims>::cell_shift_at(const point& at, double chord,
                                         std::array<double, 2>& shift) const noexcept {
  const int cell =
      cell_index(at[split_], cell_lo_, cell_width_, static_cast<int>(piece_of_cell_.size()));
  if (cell < 0 || piece_of_cell_[cell] < 0) return false;
  const std::size_t piece = static_cast<std::size_t>(piece_of_cell_[cell]);
  const box& fitted = *pieces[piece];
  const point y = trends_[piece].apply(at, split_);
  if (!fitted.contains(y, 1e-12)) return false;
  if (!(chord >= chord_lo && chord <= chord_hi)) return false;
  shift = chebyshev_box_value(fitted, y);
  return true;
}

// --- The sphere
// -----------------------------------------------------------------------------------

std::shared_ptr<const physics_table> physics_table::of(const sensor_physics_head<double>& physics,
                                                       const sensor_head<double>& head,
                                                       double radius_m,
                                                       const physics_table_range& range, long rows,
                                                       long* evaluations, int threads) {
  long spent = 0;
  if (evaluations == nullptr) evaluations = &spent;
  *evaluations = 0;
  const long budget = rows / physics_table_rows_per_evaluation;
  if (range.empty || budget < physics_table_least_evaluations || !(range.lo[0] > radius_m))
    return nullptr;
  std::shared_ptr<physics_table> table(new physics_table);
  const auto row = [&](const physics_table_point& x, sensor_physics_workspace<double>& work) {
    return physics_row_at(physics, head, radius_m, {std::hypot(x[0], radius_m), x[1], x[2]}, work);
  };
  prefetched_rows<3, decltype(row)> rows_at(row, threads);
  const auto shifts = chain_shifts_of<3>(rows_at, table->series_);
  physics_table_point lo = range.lo, hi = range.hi;
  lo[0] = horizon_distance_m(range.lo[0], radius_m);
  hi[0] = horizon_distance_m(range.hi[0], radius_m);
  table->radius_m_ = radius_m;
  if (!table->series_.build(lo, hi, shifts, budget, *evaluations)) return nullptr;
  return table;
}

bool physics_table::crossings_at(const physics_table_point& x, const crossings<double>& geometric,
                                 crossings<double>& out) const noexcept {
  const physics_table_point at{horizon_distance_m(x[0], radius_m_), x[1], x[2]};
  std::array<double, 2> shift{};
  if (!series_.shift_at(at, geometric.chord(), shift)) return false;
  // The chain's last step: the crossings from their azimuths, grazing near 0 or 180 deg.
  out = crossings_from_azimuths(geometric.phi_in + shift[0], geometric.phi_out + shift[1],
                                geometric.iterations);
  return true;
}

// --- The ellipsoid
// --------------------------------------------------------------------------------

void ellipsoid_axes_finder::add(const vec3<double>& pole) noexcept {
  if (count_ > 0)
    turn_ = turn_ + cross(last_, pole);
  else
    first_ = pole;
  sum_ = sum_ + pole;
  last_ = pole;
  ++count_;
}

ellipsoid_table_axes ellipsoid_axes_finder::axes() const noexcept {
  // The turning axis where the poles turn by more than rounding; else perpendicular to their mean.
  // The cross products are taken about the poles' mean m: sum (p_k - m) x (p_k+1 - m) = sum p_k x
  // p_k+1 - m x (p_last - p_first). About the origin, a pole coning at angle i about the axis n
  // gives each product sin^2 i n plus sin i cos i times a direction that turns with it, which
  // cancels only over whole turns: on a nearly equatorial orbit (i = 3.8 deg) a day's fraction
  // of a turn tilted w 18 deg off n, the pole's angle from w spanned 7.6 deg instead of being held,
  // and a 1.44 deg circle's build took 8 932 evaluations with 530 cells left to the chain. About
  // m (on the poles' circle's plane, as the chord p_last - p_first), what is left lies along n.
  const vec3<double> mean_pole =
      count_ > 0 ? scaled(sum_, 1.0 / static_cast<double>(count_)) : vec3<double>(0.0);
  const vec3<double> turn = turn_ - cross(mean_pole, last_ - first_);
  const double turned = norm(turn);
  vec3<double> w;
  if (turned > 1e-9) {
    w = scaled(turn, 1 / turned);
  } else {
    const double length = norm(mean_pole);
    const vec3<double> mean = length > 0 ? scaled(mean_pole, 1 / length) : vec3<double>(0, 0, 1);
    const vec3<double> other =
        std::abs(mean.x) < 0.6 ? vec3<double>(1, 0, 0) : vec3<double>(0, 1, 0);
    const vec3<double> across = cross(mean, other);
    w = scaled(across, 1 / norm(across));
  }
  const vec3<double> other = std::abs(w.x) < 0.6 ? vec3<double>(1, 0, 0) : vec3<double>(0, 1, 0);
  const vec3<double> u0 = other - scaled(w, dot(other, w));
  const vec3<double> u = scaled(u0, 1 / norm(u0));
  return {u, cross(w, u), w};
}

ellipsoid_table_point ellipsoid_table_point_of(const ellipsoid_horizon<double>& e_scan,
                                               double a_eq_m, const ellipsoid_table_axes& axes,
                                               double sin_sun_declination) noexcept {
  const vec3<double>& p = e_scan.position;  // p / a_eq, from the surface's centre
  const vec3<double>& z = e_scan.polar;
  const double pu = dot(z, axes.u), pv = dot(z, axes.v);
  // The nadir -p / |p|: its angle from S and azimuth about S.
  return {a_eq_m * std::sqrt(e_scan.height),
          std::atan2(std::hypot(p.x, p.y), -p.z),
          std::atan2(-p.y, -p.x),
          std::atan2(std::hypot(pu, pv), dot(z, axes.w)),
          std::atan2(pv, pu),
          sin_sun_declination};
}

namespace {

// The true nadir and the pole of a six-variable point, unit vectors in the scan frame.
struct table_directions {
  vec3<double> nadir, pole;
};

table_directions directions_at(const ellipsoid_table_axes& axes,
                               const ellipsoid_table_point& x) noexcept {
  const double sin_eta = std::sin(x[1]), sin_pole = std::sin(x[3]);
  return {vec3<double>(sin_eta * std::cos(x[2]), sin_eta * std::sin(x[2]), std::cos(x[1])),
          scaled(axes.u, sin_pole * std::cos(x[4])) + scaled(axes.v, sin_pole * std::sin(x[4])) +
              scaled(axes.w, std::cos(x[3]))};
}

}  // namespace

physics_table_row ellipsoid_row_at(const sensor_physics_head<double>& physics,
                                   const sensor_head<double>& head, double a_eq_m, double b_pol_m,
                                   const ellipsoid_table_axes& axes, const ellipsoid_table_point& x,
                                   sensor_physics_workspace<double>& work) noexcept {
  const table_directions d = directions_at(axes, x);
  // |P|^2 = 1 + H = |p / a|^2 (1 + kappa (z . p^)^2): the distance from the centre.
  const double kappa = (a_eq_m - b_pol_m) * (a_eq_m + b_pol_m) / (b_pol_m * b_pol_m);
  const double h = (x[0] / a_eq_m) * (x[0] / a_eq_m);
  const double along = dot(d.pole, d.nadir);
  const double r_m = a_eq_m * std::sqrt((1 + h) / (1 + kappa * along * along));
  const ellipsoid_horizon<double> e =
      ellipsoid_horizon_of(scaled(d.nadir, -r_m), d.pole, a_eq_m, b_pol_m);
  return chain_row(physics, head, head.scan_crossings(e), ellipsoid_surface_of(e, a_eq_m), x[5],
                   work);
}

physics_table_row sphere_row_at(const sensor_physics_head<double>& physics,
                                const sensor_head<double>& head, double radius_m,
                                const ellipsoid_table_axes& axes, const ellipsoid_table_point& x,
                                sensor_physics_workspace<double>& work) noexcept {
  const table_directions d = directions_at(axes, x);
  // The first variable is R sqrt(H) = sqrt(r^2 - R^2) (kappa = 0).
  const disk_trig<double> disk = disk_trig_of(radius_m, std::hypot(radius_m, x[0]));
  return chain_row(physics, head, head.scan_crossings(d.nadir, disk),
                   sphere_surface_of(d.nadir, disk, radius_m, d.pole), x[5], work);
}

template <class RowAt>
std::shared_ptr<const ellipsoid_physics_table> ellipsoid_physics_table::built(
    const ellipsoid_table_axes& axes, const physics_table_cells<6>& cells, long rows,
    long* evaluations, int threads, const RowAt& row_at) {
  long spent = 0;
  if (evaluations == nullptr) evaluations = &spent;
  *evaluations = 0;
  const long budget = rows / physics_table_rows_per_evaluation;
  if (budget < physics_table_least_evaluations) return nullptr;
  std::shared_ptr<ellipsoid_physics_table> table(new ellipsoid_physics_table);
  table->axes_ = axes;
  prefetched_rows<6, const RowAt&> rows_at(row_at, threads);
  const auto shifts = chain_shifts_of<6>(rows_at, table->series_);
  if (!table->series_.build_cells(cells, shifts, budget, *evaluations)) return nullptr;
  return table;
}

std::shared_ptr<const ellipsoid_physics_table> ellipsoid_physics_table::of(
    const sensor_physics_head<double>& physics, const sensor_head<double>& head, double a_eq_m,
    double b_pol_m, const ellipsoid_table_axes& axes, const physics_table_cells<6>& cells,
    long rows, long* evaluations, int threads) {
  return built(axes, cells, rows, evaluations, threads,
               [&](const ellipsoid_table_point& x, sensor_physics_workspace<double>& work) {
                 return ellipsoid_row_at(physics, head, a_eq_m, b_pol_m, axes, x, work);
               });
}

std::shared_ptr<const ellipsoid_physics_table> ellipsoid_physics_table::of_sphere(
    const sensor_physics_head<double>& physics, const sensor_head<double>& head, double radius_m,
    const ellipsoid_table_axes& axes, const physics_table_cells<6>& cells, long rows,
    long* evaluations, int threads) {
  return built(axes, cells, rows, evaluations, threads,
               [&](const ellipsoid_table_point& x, sensor_physics_workspace<double>& work) {
                 return sphere_row_at(physics, head, radius_m, axes, x, work);
               });
}

physics_table_cells<6> ellipsoid_physics_table::cells_for(const ellipsoid_table_range& range,
                                                          long rows) {
  const int split = range.hi[4] > range.lo[4] ? 4 : 0;
  // A cell's box spans its rows' change across it in every variable, so that with a piece's
  // offsets taken at the cells' corners, narrow cells keep the pieces thin (a day on WGS84 with the
  // season term and a field, measured: 134 s of CPU with 4096 cells, 117 s with 21 600; with the
  // later build, 1635 evaluations with 21 600 cells, 1506 with 86 400).
  physics_table_cells<6> cells(range, split,
                               static_cast<int>(std::clamp(rows, 1L, physics_table_most_cells)));
  if (split == 4) cells.split_period = 2 * pi<double>();
  return cells;
}

bool ellipsoid_physics_table::crossings_at(const ellipsoid_table_point& x,
                                           const crossings<double>& geometric,
                                           crossings<double>& out) const noexcept {
  std::array<double, 2> shift{};
  if (!series_.shift_at(x, geometric.chord(), shift)) return false;
  out = crossings_from_azimuths(geometric.phi_in + shift[0], geometric.phi_out + shift[1],
                                geometric.iterations);
  return true;
}

template class physics_series<3>;
template class physics_series<6>;

}  // namespace conescan::scene
