#include "scene/physics_table.hpp"

#include <algorithm>
#include <cmath>

#include "conescan/earth_disk.hpp"
#include "conescan/tangent_height.hpp"

namespace conescan::scene {

void physics_table_range::add(const physics_table_point& x) noexcept {
  for (int d = 0; d < 3; ++d) {
    lo[d] = empty ? x[d] : std::min(lo[d], x[d]);
    hi[d] = empty ? x[d] : std::max(hi[d], x[d]);
  }
  empty = false;
}

std::shared_ptr<const physics_table> physics_table::of(
    const sensor_physics_fast_head<double>& physics, const sensor_head<double>& head,
    double radius_m, const physics_table_range& range, long rows, long* evaluations) {
  if (evaluations != nullptr) *evaluations = 0;
  if (range.empty) return nullptr;
  auto work = std::make_unique<sensor_physics_fast_workspace<double>>();
  // The chain at a point of the box, as simulation::physics_crossings runs it on a row there.
  auto shifts = [&](const physics_table_point& x, std::array<double, 2>& out) {
    const double sin_eta = std::sin(x[1]);
    const vec3<double> nadir(sin_eta * std::cos(x[2]), sin_eta * std::sin(x[2]), std::cos(x[1]));
    const disk_trig<double> disk = disk_trig_of(radius_m, x[0]);
    const crossings<double> geometric = head.scan_crossings(nadir, disk);
    if (geometric.state != status::ok) return false;
    const sphere_surface<double> sphere = sphere_surface_of(nadir, disk, radius_m, nadir);
    const crossings<double> c =
        sensor_physics_fast_crossings(physics, head.circle(), sphere, 0.0, geometric, *work);
    if (c.state != status::ok) return false;
    out = {c.phi_in - geometric.phi_in, c.phi_out - geometric.phi_out};
    return true;
  };
  std::shared_ptr<physics_table> table(new physics_table);
  table->box_ = std::make_unique<chebyshev_box<double, 2, 4096>>();
  table->report_ =
      chebyshev_box_build(*table->box_, range.lo, range.hi, shifts, physics_table_tolerance_rad,
                          rows / physics_table_rows_per_evaluation);
  if (evaluations != nullptr) *evaluations = table->report_.evaluations;
  if (!table->report_.ok) return nullptr;
  return table;
}

bool physics_table::crossings_at(const physics_table_point& x, const crossings<double>& geometric,
                                 crossings<double>& out) const noexcept {
  // A held variable is the same double on every row (a constant attitude): no slack needed
  // beyond rounding.
  if (!box_->contains(x, 1e-12)) return false;
  const std::array<double, 2> shift = chebyshev_box_value(*box_, x);
  out = geometric;
  out.phi_in += shift[0];
  out.phi_out += shift[1];
  return true;
}

}  // namespace conescan::scene
