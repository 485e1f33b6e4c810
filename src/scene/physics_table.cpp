#include "scene/physics_table.hpp"

#include <algorithm>
#include <cmath>

#include "conescan/earth_disk.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/sensor_physics/height.hpp"

namespace conescan::scene {

void physics_table_range::add(const physics_table_point& x) noexcept {
  for (int d = 0; d < 3; ++d) {
    lo[d] = empty ? x[d] : std::min(lo[d], x[d]);
    hi[d] = empty ? x[d] : std::max(hi[d], x[d]);
  }
  empty = false;
}

physics_table_row physics_row_at(const sensor_physics_head<double>& physics,
                                 const sensor_head<double>& head, double radius_m,
                                 const physics_table_point& x,
                                 sensor_physics_workspace<double>& work) noexcept {
  const double sin_eta = std::sin(x[1]);
  const vec3<double> nadir(sin_eta * std::cos(x[2]), sin_eta * std::sin(x[2]), std::cos(x[1]));
  const disk_trig<double> disk = disk_trig_of(radius_m, x[0]);
  physics_table_row row{head.scan_crossings(nadir, disk), {}};
  if (row.geometric.state != status::ok) {
    row.physics = crossings<double>::failed(row.geometric.state);
    return row;
  }
  // The polar axis serves only the season term, which a table's scene has not: any unit vector.
  const sphere_surface<double> sphere = sphere_surface_of(nadir, disk, radius_m, nadir);
  row.physics = sensor_physics_crossings(physics, head.circle(), sphere, 0.0, row.geometric, work);
  return row;
}

namespace {

// The table's first variable: the distance to the horizon, sqrt(r^2 - R^2), in which the shifts
// are smoother than in r itself (a third fewer nodes over the paper's ellipse, measured); NaN
// inside the sphere.
double horizon_distance_m(double r_m, double radius_m) {
  return std::sqrt((r_m - radius_m) * (r_m + radius_m));
}

// The chain at a point of the table's box, as simulation::physics_crossings runs it on a row
// there: the two crossings' shifts from the geometric ones, or false where either is not ok.
// Records the geometric chords it saw (chord_lo, chord_hi): a row is trusted to the table only
// within them.
struct chain_shifts {
  const sensor_physics_head<double>& physics;
  const sensor_head<double>& head;
  double radius_m;
  sensor_physics_workspace<double>& work;
  double* chord_lo;
  double* chord_hi;

  bool operator()(const physics_table_point& x, std::array<double, 2>& out) const {
    const physics_table_row row =
        physics_row_at(physics, head, radius_m, {std::hypot(x[0], radius_m), x[1], x[2]}, work);
    if (row.physics.state != status::ok) return false;
    const crossings<double>& geometric = row.geometric;
    out = {row.physics.phi_in - geometric.phi_in, row.physics.phi_out - geometric.phi_out};
    *chord_lo = std::min(*chord_lo, geometric.chord());
    *chord_hi = std::max(*chord_hi, geometric.chord());
    return true;
  }
};

// Where the nadir wanders (two or three variables), the distance is cut into pieces of about a
// dozen nodes each, so that a row's series has fewer terms (docs/SENSOR_PHYSICS.md, "The table").
int piece_count(const std::array<int, 3>& whole_box_nodes) {
  if (whole_box_nodes[1] * whole_box_nodes[2] == 1) return 1;
  return std::clamp(
      (whole_box_nodes[0] + physics_table_piece_nodes - 1) / physics_table_piece_nodes, 1,
      physics_table_most_pieces);
}

}  // namespace

std::shared_ptr<const physics_table> physics_table::of(const sensor_physics_head<double>& physics,
                                                       const sensor_head<double>& head,
                                                       double radius_m,
                                                       const physics_table_range& range, long rows,
                                                       long* evaluations) {
  long spent = 0;
  if (evaluations == nullptr) evaluations = &spent;
  *evaluations = 0;
  const long budget = rows / physics_table_rows_per_evaluation;
  if (range.empty || budget < physics_table_least_evaluations || !(range.lo[0] > radius_m))
    return nullptr;
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  std::shared_ptr<physics_table> table(new physics_table);
  table->chord_lo_ = 2 * pi<double>();
  table->chord_hi_ = 0;
  const chain_shifts shifts{physics, head, radius_m, *work, &table->chord_lo_, &table->chord_hi_};
  physics_table_point lo = range.lo, hi = range.hi;
  lo[0] = horizon_distance_m(range.lo[0], radius_m);
  hi[0] = horizon_distance_m(range.hi[0], radius_m);
  const chebyshev_box_report<double> plan =
      chebyshev_box_nodes<double, 2>(lo, hi, shifts, physics_table_tolerance_rad, budget);
  *evaluations = plan.evaluations;
  if (!plan.ok) return nullptr;
  const int pieces = piece_count(plan.nodes);
  table->radius_m_ = radius_m;
  table->lo_m_ = lo[0];
  table->width_m_ = (hi[0] - lo[0]) / pieces;
  table->report_.ok = true;
  table->report_.nodes = {0, 0, 0};
  for (int p = 0; p < pieces; ++p) {
    physics_table_point piece_lo = lo, piece_hi = hi;
    piece_lo[0] = lo[0] + p * table->width_m_;
    piece_hi[0] = p + 1 == pieces ? hi[0] : lo[0] + (p + 1) * table->width_m_;
    if (!table->add_piece(piece_lo, piece_hi, pieces > 1 ? 0 : plan.nodes[0], plan.nodes, shifts,
                          budget, *evaluations))
      return nullptr;
  }
  table->report_.evaluations = *evaluations;
  return table;
}

template <class Shifts>
bool physics_table::add_piece(const physics_table_point& lo, const physics_table_point& hi,
                              int distance_nodes, const std::array<int, 3>& angle_nodes,
                              const Shifts& shifts, long budget, long& evaluations) {
  // The angles' nodes hold for every piece; the distance's are the piece's own (0: sweep it).
  std::array<int, 3> nodes = angle_nodes;
  nodes[0] = distance_nodes != 0
                 ? distance_nodes
                 : chebyshev_variable_nodes<double, 2>(
                       lo, hi, 0, shifts, physics_table_tolerance_rad, budget, evaluations);
  if (nodes[0] == 0) return false;
  auto box = std::make_unique<chebyshev_box<double, 2, 4096>>();
  const chebyshev_box_report<double> built = chebyshev_box_fit_checked(
      *box, lo, hi, nodes, shifts, physics_table_tolerance_rad, budget - evaluations);
  evaluations += built.evaluations;
  if (!built.ok) return false;
  for (int d = 0; d < 3; ++d) report_.nodes[d] = std::max(report_.nodes[d], built.nodes[d]);
  report_.worst_check = std::max(report_.worst_check, built.worst_check);
  pieces_.push_back(std::move(box));
  return true;
}

bool physics_table::crossings_at(const physics_table_point& x, const crossings<double>& geometric,
                                 crossings<double>& out) const noexcept {
  const physics_table_point at{horizon_distance_m(x[0], radius_m_), x[1], x[2]};
  const double place = width_m_ > 0 ? (at[0] - lo_m_) / width_m_ : 0.0;
  if (!(place >= 0)) return false;  // below the box, or NaN
  const std::size_t piece = std::min(pieces_.size() - 1, static_cast<std::size_t>(place));
  // A held variable is the same double on every row (a constant attitude): no slack needed
  // beyond rounding.
  const chebyshev_box<double, 2, 4096>& box = *pieces_[piece];
  if (!box.contains(at, 1e-12)) return false;
  // At a chord the build never saw the row is the chain's. Every chord it saw passed the chain's
  // own checks on the chord (physics_detail::row_status: the field narrower than the chord, the
  // lag's memory within the sky's arc), so a chord they refuse lies outside these too.
  const double chord = geometric.chord();
  if (!(chord >= chord_lo_ && chord <= chord_hi_)) return false;
  const std::array<double, 2> shift = chebyshev_box_value(box, at);
  // The chain's last step: the crossings from their azimuths, grazing near 0 or 180 deg.
  out = crossings_from_azimuths(geometric.phi_in + shift[0], geometric.phi_out + shift[1],
                                geometric.iterations);
  return true;
}

}  // namespace conescan::scene
