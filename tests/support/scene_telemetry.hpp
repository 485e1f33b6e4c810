// The telemetry conescan-sim would write for a scene, as the calibration's reader holds it: for
// the tests and benchmarks of the calibration on real scenes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "calibration/layout.hpp"
#include "calibration/telemetry.hpp"
#include "conescan/status.hpp"
#include "simulation/simulation.hpp"

namespace conescan_test {

/// The chords and phases conescan-sim computes for `truth` in run `run`, as the calibration's
/// reader holds them (rows whose head is not ok counted as skipped); `corrupt(row, head, chord,
/// phase)` may change each measurement (degrees) before it is kept.
template <class Corrupt>
conescan::calibration::telemetry simulated_telemetry(const conescan::scene::loaded_scene& truth,
                                                     std::uint64_t run, Corrupt corrupt) {
  namespace cal = conescan::calibration;
  const conescan::scene::simulation sim = conescan::scene::simulation::of(truth).value();
  cal::telemetry t;
  t.skipped_per_head.assign(sim.head_count(), 0);
  t.observations.reserve(sim.rows() * sim.head_count());
  conescan::scene::row row = sim.make_row();
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    sim.compute(k, row, run);
    for (std::size_t h = 0; h < sim.head_count(); ++h) {
      if (row.heads[h].state != conescan::status::ok) {
        ++t.skipped_per_head[h];
        continue;
      }
      double chord = row.heads[h].chord_rad / cal::radians_per_degree;
      double phase = row.heads[h].phase_rad / cal::radians_per_degree;
      corrupt(k, h, chord, phase);
      t.observations.push_back({{static_cast<std::size_t>(k), row.t_s, h}, chord, phase});
    }
  }
  t.row_count = sim.rows();
  return t;
}

/// The same, unchanged.
inline conescan::calibration::telemetry simulated_telemetry(
    const conescan::scene::loaded_scene& truth, std::uint64_t run = 0) {
  return simulated_telemetry(truth, run, [](std::uint64_t, std::size_t, double&, double&) {});
}

}  // namespace conescan_test
