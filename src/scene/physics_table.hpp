// The sensor physics by table (MODEL §12; docs/SENSOR_PHYSICS.md, "The table"). On a sphere
// without the season term, a head's physics crossings shift its geometric ones by amounts that
// depend on the row through three numbers only: the satellite's distance from the centre and the
// true nadir's angle from the spin axis and azimuth about it. A scene with many rows tabulates
// those shifts once per head, as a tensor Chebyshev series over the box its rows visit
// (conescan/chebyshev_box.hpp), fitted to the chain (sensor_physics/chain.hpp) and checked against
// it; a row inside the box then costs one evaluation of the series, and every other row runs the
// chain.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "conescan/chebyshev_box.hpp"
#include "conescan/crossings.hpp"
#include "conescan/sensor_head.hpp"
#include "conescan/sensor_physics.hpp"

namespace conescan::scene {

/// The table's variables at one row: distance (m), the nadir's angle from S and its azimuth
/// about S (rad).
using physics_table_point = std::array<double, 3>;

/// The box a head's rows visit (lo, hi per variable).
struct physics_table_range {
  physics_table_point lo{}, hi{};
  bool empty = true;
  void add(const physics_table_point& x) noexcept;
};

/// The accuracy the table is built to, against the chain: 1e-7 deg on each crossing at the
/// build's check points (corners and 16 inside a piece). Between them the series can differ by
/// more where the chain is not smooth (docs/SENSOR_PHYSICS.md, "The table", with the figures
/// measured).
inline constexpr double physics_table_tolerance_rad = 1e-7 * 3.14159265358979323846 / 180;

/// The evaluations of the chain a table may cost, as a share of the rows it would serve: at most
/// a quarter of what running the chain on every row costs, or it is not built.
inline constexpr long physics_table_rows_per_evaluation = 4;
/// Where the nadir wanders, the distance's pieces: about this many nodes each, at most this many.
inline constexpr int physics_table_piece_nodes = 12;
inline constexpr int physics_table_most_pieces = 8;
/// Fewer evaluations than this build no table of the three variables: no attempt is made.
inline constexpr long physics_table_least_evaluations = 64;

/// A row at x (distance from the centre, m; the nadir's angle from S and azimuth about it, rad)
/// on the sphere of radius `radius_m`, without the season term: its geometric crossings and the
/// chain's, as simulation::physics_crossings computes them (the physics failed with the
/// geometric status where that is not ok). What the table tabulates, and what tests compare
/// it with.
struct physics_table_row {
  crossings<double> geometric, physics;
};
physics_table_row physics_row_at(const sensor_physics_head<double>& physics,
                                 const sensor_head<double>& head, double radius_m,
                                 const physics_table_point& x,
                                 sensor_physics_workspace<double>& work) noexcept;

class physics_table {
 public:
  /// The table of one head over `range`, on the sphere of radius `radius_m`, or null where it does
  /// not pay (fewer than 4 * 64 rows, or more evaluations than a quarter of the rows) or cannot be
  /// trusted (a check point off by more than the tolerance, a node where the chain gives no ok
  /// crossings); `evaluations` gets the chain evaluations spent either way.
  static std::shared_ptr<const physics_table> of(const sensor_physics_head<double>& physics,
                                                 const sensor_head<double>& head, double radius_m,
                                                 const physics_table_range& range, long rows,
                                                 long* evaluations = nullptr);

  /// The physics crossings of a row at x whose geometric crossings are `geometric` (ok), or
  /// false where the row is the chain's: x outside the box, or a geometric chord beyond those the
  /// build saw (which includes every chord the chain refuses: the field wider than the chord, the
  /// lag's memory longer than the sky's arc). The result's status is ok or grazing (a half chord
  /// within 0.1 deg of 0 or 180 deg), as the chain's last step says.
  bool crossings_at(const physics_table_point& x, const crossings<double>& geometric,
                    crossings<double>& out) const noexcept;

  /// The build: evaluations spent, the largest node counts of any piece, the worst check.
  const chebyshev_box_report<double>& report() const noexcept { return report_; }
  std::size_t pieces() const noexcept { return pieces_.size(); }

 private:
  /// Fits and checks the piece [lo, hi] (distance_nodes 0: its own sweep of the distance), within
  /// what is left of `budget`; false where it cannot be trusted.
  template <class Shifts>
  bool add_piece(const physics_table_point& lo, const physics_table_point& hi, int distance_nodes,
                 const std::array<int, 3>& angle_nodes, const Shifts& shifts, long budget,
                 long& evaluations);

  // Equal pieces of the distance's range, from lo_m_, each its own box over the angles' range.
  std::vector<std::unique_ptr<chebyshev_box<double, 2, 4096>>> pieces_;
  double radius_m_ = 0;  // R: the first variable is sqrt(r^2 - R^2)
  // The geometric chords of every point the build evaluated: a row is the table's only within.
  double chord_lo_ = 0, chord_hi_ = 0;
  double lo_m_ = 0, width_m_ = 0;
  chebyshev_box_report<double> report_;
};

}  // namespace conescan::scene
