// The sensor physics by table (MODEL §12; docs/SENSOR_PHYSICS.md, "The table"). On a sphere
// without the season term, a head's physics crossings shift its geometric ones by amounts that
// depend on the row through three numbers only: the satellite's distance from the centre and the
// true nadir's angle from the spin axis and azimuth about it. On the ellipsoid, with or without
// the season term, and on the sphere with it, six: the distance to the horizon, the nadir's two
// angles, the pole's two angles in a frame fixed in the scan frame, and the sine of the Sun's
// declination. A scene with many rows tabulates those shifts once per head, as a tensor
// Chebyshev series over the box its rows visit (conescan/chebyshev_box.hpp), fitted to the chain
// (sensor_physics/chain.hpp) and checked against it; a row inside the box then costs one
// evaluation of the series, and every other row runs the chain.
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "conescan/chebyshev_box.hpp"
#include "conescan/crossings.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/sensor_head.hpp"
#include "conescan/sensor_physics.hpp"

namespace conescan::scene {

/// The table's variables at one row: distance (m), the nadir's angle from S and its azimuth
/// about S (rad).
using physics_table_point = std::array<double, 3>;

/// The box a head's rows visit (lo, hi per variable).
template <int Dims>
struct basic_physics_table_range {
  std::array<double, Dims> lo{}, hi{};
  bool empty = true;
  void add(const std::array<double, Dims>& x) noexcept;
};
using physics_table_range = basic_physics_table_range<3>;

/// The pieces a table of cells starts from (over a period of the split variable: for the pole's
/// azimuth, an orbit), and the share of a period below which the rows' span starts from fewer
/// (physics_series::build_cells).
inline constexpr int physics_table_first_pieces = 8;
inline constexpr double physics_table_short_span = 0.25;

/// The rows' boxes cell by cell along one variable (`split`): equal cells over its range, each the
/// box of the rows that fall in it. A scene's rows visit a thin subset of the variables (on an
/// orbit the distance is a function of the pole's azimuth): a piece over some cells is the box of
/// those cells' rows, not the whole box's slice.
///
/// A cell's box spans its rows' change across it: on an orbit the distance changes some 110 m
/// across a cell of a day's 86 400, which a box's corners keep however well the rows follow a
/// curve. An optional second pass (`add_along`) records each cell's rows along the line through its
/// neighbours' middles instead (the box of x_d - slope_d (x_split - middle)), whose width is the
/// rows' own spread about the curve: a two-body orbit's distance then spans millimetres.
template <int Dims>
struct physics_table_cells {
  int split = 0;
  double lo = 0, width = 0;
  /// The split variable's period (2 pi for an angle that turns), 0 for none: build_cells starts
  /// from eight pieces, fewer where the rows span less than a quarter of it.
  double split_period = 0;
  std::vector<basic_physics_table_range<Dims>> cells;
  std::vector<long> rows;  // each cell's rows
  // After add_along's pass: each cell's slopes (d x_d / d x_split) and rows along them.
  std::vector<std::array<double, Dims>> slopes;
  std::vector<basic_physics_table_range<Dims>> along;

  /// `count` cells of variable `split` over the whole box `range` (one where it is held).
  physics_table_cells(const basic_physics_table_range<Dims>& range, int split_variable, int count);
  /// The cell of x, or -1 outside the range.
  int cell_of(const std::array<double, Dims>& x) const noexcept;
  /// A row at x, standing for `count` rows (a benchmark's or a test's row for many of a day's).
  void add(const std::array<double, Dims>& x, long count = 1) noexcept;
  /// The second pass, after every row's add: the same row again.
  void add_along(const std::array<double, Dims>& x) noexcept;
  /// The box of the cell's rows at x_split = at, inside or at the ends of the cell: the rows
  /// carried along the cell's slopes where the second pass ran, else the cell's box.
  basic_physics_table_range<Dims> rows_at(int cell, double at) const noexcept;
  /// The cell's middle in the split variable (its rows' box's).
  double middle_of(int cell) const noexcept;

 private:
  void fit_slopes();
};

/// The accuracy the table is built to, against the chain: 1e-7 deg on each crossing at the
/// build's check points (a piece's corners and 16 points inside it on the sphere; on the ellipsoid
/// 8 and the values its plan read). Between them the series can differ by more where the chain is
/// not smooth (docs/SENSOR_PHYSICS.md, "The table", with the figures measured).
inline constexpr double physics_table_tolerance_rad = 1e-7 * 3.14159265358979323846 / 180;

/// The ellipsoid table's checks of a piece spread over its box (a Weyl sequence), beside its
/// corners and the values its plan read (physics_series::checked_piece).
inline constexpr int physics_table_spread_checks = 8;

/// A piece's variable whose offsets span less than this share of its size is planned as held
/// (physics_series::plan_range).
inline constexpr double physics_table_negligible_span = 1e-10;

/// The evaluations of the chain a table may cost, as a share of the rows it would serve: at most
/// a quarter of what running the chain on every row costs, or it is not built.
inline constexpr long physics_table_rows_per_evaluation = 4;
/// Where the nadir wanders, the distance's pieces: about this many nodes each, at most this many.
inline constexpr int physics_table_piece_nodes = 12;
inline constexpr int physics_table_most_pieces = 8;
/// Fewer evaluations than this build no table of the three variables: no attempt is made.
inline constexpr long physics_table_least_evaluations = 64;
/// A field's head on the ellipsoid is tabulated only where its rows allow this many evaluations
/// (512 rows), each a chain of milliseconds. Its builds, measured on the paper's ellipse at 1 s
/// with the season term and a 1.5 deg square, take some 850 evaluations for a day's rows and some
/// 90 for 20 minutes'; where the budget runs out, the pieces built serve their rows and the rest
/// run the chain. CPU against the chain on every row (docs/SENSOR_PHYSICS.md, decision 26): 512
/// rows at 1 s 0.7 s against 4.4 s; 400 rows from perigee 5.2 s against 3.4 s (the build ran
/// out); 512 rows at 10 s, most of an orbit, 5.3 s against 4.4 s.
inline constexpr long physics_table_least_field_evaluations = 128;
/// A piece of the ellipsoid's table costs at least this many evaluations (its sweeps, its nodes,
/// the points and corners that check it: the smallest pieces of a day's build on WGS84 with the
/// season term took 43, measured, with 16 spread checks where there are 8 now): cells with fewer
/// rows are the chain's, which costs an evaluation a row, and a piece that fails with fewer than
/// twice as many is not halved.
inline constexpr long physics_table_least_piece_evaluations = 40;
/// The ellipsoid table's cells along its split variable, at most (a day and a half at 1 s has one
/// per row; with the second pass, at most 35 MB a head while the table is built).
inline constexpr long physics_table_most_cells = 131072;

/// A row at x (distance from the centre, m; the nadir's angle from S and azimuth about it, rad)
/// on the sphere of radius `radius_m`, without the season term: its geometric crossings and the
/// chain's, as simulation::physics_crossings computes them (the physics failed with the
/// geometric status where that is not ok). What the table tabulates, and what tests compare
/// it with.
struct physics_table_row {
  crossings<double> geometric, physics;
  /// The part of the pulse that gave the normalised locator's peak (the chain's
  /// sensor_physics_workspace::peak_part; -1 where it took none).
  int peak_part = -1;
};
physics_table_row physics_row_at(const sensor_physics_head<double>& physics,
                                 const sensor_head<double>& head, double radius_m,
                                 const physics_table_point& x,
                                 sensor_physics_workspace<double>& work) noexcept;

/// One head's shifts over pieces of the first variable's range, checked against the chain at
/// every piece's corners and points inside it: the part the sphere's and the ellipsoid's tables
/// share. Built by physics_table::of and ellipsoid_physics_table::of.
template <int Dims>
class physics_series {
 public:
  using point = std::array<double, Dims>;
  using box = chebyshev_box<double, 2, 4096, Dims>;

  /// Fits the shifts over [lo, hi] (the first variable cut in pieces where any other varies)
  /// within `budget` evaluations; false where it does not pay or cannot be trusted. `shifts`
  /// records the geometric chords it saw in chord_lo, chord_hi.
  template <class Shifts>
  bool build(const point& lo, const point& hi, const Shifts& shifts, long budget,
             long& evaluations);
  /// Fits the shifts piece by piece over the cells' rows: eight pieces of equal cells (one or two
  /// where the rows span less than a quarter of the split variable's period), each the box of its
  /// cells' rows. A piece whose series does not hold is cut where the normalised locator's peak
  /// moves from one part of the pulse to another (a kink of the chain's output), the one or two
  /// cells that hold the move left to the chain; one without such a move is halved until it
  /// holds. A single cell that still does not, and cells whose rows cost the chain fewer
  /// evaluations than a piece would, are left to the chain, and so is the nearest cell with rows
  /// on either side of them (a margin where the chain refuses rows). Where the budget runs out, the
  /// pieces built so far serve their rows and every other row is the chain's (their evaluations are
  /// spent either way); false where no piece was built.
  template <class Shifts>
  bool build_cells(const physics_table_cells<Dims>& cells, const Shifts& shifts, long budget,
                   long& evaluations);
  /// The shifts at `at` (the table's variables) for a row whose geometric chord is `chord`, or
  /// false where the row is the chain's (outside the box, or a chord the build never saw).
  bool shift_at(const point& at, double chord, std::array<double, 2>& shift) const noexcept;

  double chord_lo = 0, chord_hi = 0;  // the geometric chords of every point the build evaluated
  int last_peak_part = -1;            // the peak's part at the build's last evaluation
  chebyshev_box_report<double, Dims> report;
  std::vector<std::unique_ptr<box>> pieces;
  int chain_cells = 0;  // build_cells: cells with rows that no piece serves

 private:
  template <class Shifts>
  bool add_piece(const point& lo, const point& hi, int distance_nodes,
                 const std::array<int, Dims>& angle_nodes, const Shifts& shifts, long budget,
                 long& evaluations);
  bool cell_shift_at(const point& at, double chord, std::array<double, 2>& shift) const noexcept;
  template <class Shifts>
  void add_cells(const physics_table_cells<Dims>& cells, int first, int last, const Shifts& shifts,
                 long budget, long& evaluations);
  // A value of the shifts the chain gave at `at` while a piece was planned (ok false: none), and
  // the peak's part there.
  struct known_shift {
    point at{};
    std::array<double, 2> shifts{};
    int part = -1;
    bool ok = false;
  };
  std::vector<std::pair<double, int>> split_sweep(
      const std::vector<known_shift>& known, const basic_physics_table_range<Dims>& planned) const;
  template <class Offsets>
  std::unique_ptr<box> checked_piece(const basic_physics_table_range<Dims>& range,
                                     const std::array<int, Dims>& nodes, const Offsets& offsets,
                                     const std::vector<known_shift>& known, long budget,
                                     long& evaluations);
  /// The cells [lo, hi] of a piece that hold the first place along its split variable where the
  /// peak's part changes (a kink of the crossings), or false; `places` are the places along it
  /// (through the piece's middle) where the peak's part is known, with the part (-1: the chain
  /// failed there).
  template <class Offsets>
  bool peak_switch_cells(int first, int last, const basic_physics_table_range<Dims>& range,
                         const Offsets& offsets, std::vector<std::pair<double, int>> places,
                         long budget, long& evaluations, int& lo, int& hi);
  double lo_m_ = 0, width_m_ = 0;  // equal pieces of the first variable's range, from lo_m_
  // build_cells: the cells' variable and layout, and each cell's piece (-1: the chain's).
  int split_ = -1;
  // build_cells: each piece's variables are offsets from a polynomial in the split variable
  // through its cells' rows (x_d - p_d(x_split); the split variable itself as it is), so that a
  // piece of an orbit's rows is a thin box: over an eighth of the paper's ellipse a line leaves the
  // distance up to 160 km off, five to eight nodes; a cubic up to 354 m, two; degree 11 (with the
  // cells' rows along their curve) a millimetre on a two-body orbit, one. Each variable takes the
  // least degree that does nearly as well as any (fit_trend, cut_trend).
  struct trend {
    static constexpr int terms = 12;  // T_0 .. T_11 in t = (x_split - middle) / half
    double middle = 0, half = 0;
    std::array<std::array<double, terms>, std::size_t{Dims}> coefficients{};
    double t_of(double x_split) const noexcept {
      return half > 0 ? (x_split - middle) / half : 0.0;
    }
    /// Every variable's polynomial at x_split (0 for the split variable).
    point values_at(double x_split) const noexcept;
    point apply(const point& x, int split) const noexcept;
    /// apply's inverse: the row's variables at offsets y.
    point unapply(const point& y, int split) const noexcept;
  };
  std::vector<trend> trends_;
  void fit_trend(const physics_table_cells<Dims>& cells, int first, int last, trend& line) const;
  void cut_trend(const physics_table_cells<Dims>& cells, int first, int last, trend& line) const;
  basic_physics_table_range<Dims> plan_range(const basic_physics_table_range<Dims>& range,
                                             const trend& line) const;
  basic_physics_table_range<Dims> offset_box(const physics_table_cells<Dims>& cells, int first,
                                             int last, const trend& line) const;
  void keep_piece(int first, int last, std::unique_ptr<box> fitted, const trend& line);
  double cell_lo_ = 0, cell_width_ = 0;
  std::vector<int> piece_of_cell_;
};

class physics_table {
 public:
  /// The table of one head over `range`, on the sphere of radius `radius_m`, or null where it does
  /// not pay (fewer than 4 * 64 rows, or more evaluations than a quarter of the rows) or cannot be
  /// trusted (a check point off by more than the tolerance, a node where the chain gives no ok
  /// crossings); `evaluations` gets the chain evaluations spent either way. The chain runs on up
  /// to `threads` threads where the build asks for several points at once (its nodes, checks and
  /// sweeps): the same table, to the bit, on any number.
  static std::shared_ptr<const physics_table> of(const sensor_physics_head<double>& physics,
                                                 const sensor_head<double>& head, double radius_m,
                                                 const physics_table_range& range, long rows,
                                                 long* evaluations = nullptr, int threads = 1);

  /// The physics crossings of a row at x whose geometric crossings are `geometric` (ok), or
  /// false where the row is the chain's: x outside the box, or a geometric chord beyond those the
  /// build saw (which includes every chord the chain refuses: the field wider than the chord, the
  /// lag's memory longer than the sky's arc). The result's status is ok or grazing (a half chord
  /// within 0.1 deg of 0 or 180 deg), as the chain's last step says.
  bool crossings_at(const physics_table_point& x, const crossings<double>& geometric,
                    crossings<double>& out) const noexcept;

  /// The build: evaluations spent, the largest node counts of any piece, the worst check.
  const chebyshev_box_report<double>& report() const noexcept { return series_.report; }
  std::size_t pieces() const noexcept { return series_.pieces.size(); }

 private:
  physics_series<3> series_;
  double radius_m_ = 0;  // R: the first variable is sqrt(r^2 - R^2)
};

// --- The ellipsoid, with or without the season term; the sphere with it -------------------------

/// The ellipsoid table's variables at one row: the distance to the horizon in the scaled space of
/// MODEL §5 (a_eq sqrt(H), m), the true nadir's angle from S and azimuth about S (the centre's
/// direction), the pole's angle from the axes' w and azimuth about it from u (rad), and the sine
/// of the Sun's declination.
using ellipsoid_table_point = std::array<double, 6>;
using ellipsoid_table_range = basic_physics_table_range<6>;

/// The frame, fixed in the scan frame, of the pole's two angles (right-handed, unit): where the
/// scene's pole turns about one axis (an orbit-referenced attitude), w is that axis, so that the
/// pole's angle from it is held and its azimuth about it the one variable the orbit moves.
struct ellipsoid_table_axes {
  vec3<double> u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0}, w{0.0, 0.0, 1.0};
};

/// The axes about which a sequence of unit poles turns: w along the sum of consecutive poles'
/// cross products taken about their mean (their rotation axis, whatever fraction of a turn they
/// make), or, where they do not turn, any axis perpendicular to their mean (the pole's angle from
/// w is then held at 90 deg). Only the table's cost depends on the choice.
class ellipsoid_axes_finder {
 public:
  void add(const vec3<double>& pole) noexcept;
  ellipsoid_table_axes axes() const noexcept;

 private:
  vec3<double> turn_{0.0}, sum_{0.0}, first_{0.0}, last_{0.0};
  long count_ = 0;
};

/// The variables of a row whose ellipsoid (MODEL §5) is `e_scan` in the head's scan frame.
ellipsoid_table_point ellipsoid_table_point_of(const ellipsoid_horizon<double>& e_scan,
                                               double a_eq_m, const ellipsoid_table_axes& axes,
                                               double sin_sun_declination) noexcept;

/// A row at x on the ellipsoid of semi-axes a_eq_m, b_pol_m: its geometric crossings and the
/// chain's, as simulation::physics_crossings computes them (the physics failed with the geometric
/// status where that is not ok).
physics_table_row ellipsoid_row_at(const sensor_physics_head<double>& physics,
                                   const sensor_head<double>& head, double a_eq_m, double b_pol_m,
                                   const ellipsoid_table_axes& axes, const ellipsoid_table_point& x,
                                   sensor_physics_workspace<double>& work) noexcept;

/// The same on the sphere of radius `radius_m` with the season term (x from
/// ellipsoid_table_point_of on the sphere as an ellipsoid of semi-axes radius_m, radius_m): the
/// sphere's chain, as simulation::physics_crossings runs it (its season term's latitude WGS84's
/// geodetic latitude of the sphere's point, MODEL §12; not the ellipsoid chain's on a = b).
physics_table_row sphere_row_at(const sensor_physics_head<double>& physics,
                                const sensor_head<double>& head, double radius_m,
                                const ellipsoid_table_axes& axes, const ellipsoid_table_point& x,
                                sensor_physics_workspace<double>& work) noexcept;

class ellipsoid_physics_table {
 public:
  /// As physics_table::of, on the ellipsoid of semi-axes a_eq_m, b_pol_m (the one every row of
  /// the scene has), the pole's angles in `axes`.
  static std::shared_ptr<const ellipsoid_physics_table> of(
      const sensor_physics_head<double>& physics, const sensor_head<double>& head, double a_eq_m,
      double b_pol_m, const ellipsoid_table_axes& axes, const physics_table_cells<6>& cells,
      long rows, long* evaluations = nullptr, int threads = 1);
  /// The same on the sphere of radius `radius_m` with the season term (sphere_row_at): the
  /// sphere's rows then vary in the same six variables, the pole's two angles the season term's.
  static std::shared_ptr<const ellipsoid_physics_table> of_sphere(
      const sensor_physics_head<double>& physics, const sensor_head<double>& head, double radius_m,
      const ellipsoid_table_axes& axes, const physics_table_cells<6>& cells, long rows,
      long* evaluations = nullptr, int threads = 1);
  /// The cells a table is built over: one per row, at most physics_table_most_cells, along
  /// the pole's azimuth where it varies, else along the distance.
  static physics_table_cells<6> cells_for(const ellipsoid_table_range& range, long rows);

  /// As physics_table::crossings_at, x from ellipsoid_table_point_of with the table's axes on the
  /// table's ellipsoid.
  bool crossings_at(const ellipsoid_table_point& x, const crossings<double>& geometric,
                    crossings<double>& out) const noexcept;

  const chebyshev_box_report<double, 6>& report() const noexcept { return series_.report; }
  std::size_t pieces() const noexcept { return series_.pieces.size(); }
  /// The cells left to the chain (no series held there).
  int chain_cells() const noexcept { return series_.chain_cells; }
  const ellipsoid_table_axes& axes() const noexcept { return axes_; }

 private:
  template <class RowAt>
  static std::shared_ptr<const ellipsoid_physics_table> built(const ellipsoid_table_axes& axes,
                                                              const physics_table_cells<6>& cells,
                                                              long rows, long* evaluations,
                                                              int threads, const RowAt& row_at);
  physics_series<6> series_;
  ellipsoid_table_axes axes_;
};

}  // namespace conescan::scene
