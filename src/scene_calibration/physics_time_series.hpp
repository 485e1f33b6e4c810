// A head's sensor-physics shifts along the telemetry's time, for the fit (MODEL §11, §12;
// docs/CALIBRATION.md, "Fitting the sensor physics"): the chain's crossings less the geometric
// ones, interpolated in time between the rows where the chain ran, at one set of the model's
// inputs at a time.
//
// Why: the fit asks every row's crossings at every step, with their derivatives, and the chain
// costs 0.1 ms (a pencil with lag) to 10 ms (a 1.5 deg field) a row in double, some 5 to 20 times
// that with the fit's Jets. Within one step the inputs are the same for every row (a drifting
// parameter's segment aside), and the shifts change smoothly along the orbit: a piece of the time
// axis takes the chain at its nodes (Chebyshev-Lobatto points snapped to rows) and gives every
// row between them its shifts and their gradients by barycentric interpolation, checked against
// the chain at rows between the nodes. A piece whose nodes or checks fail is halved, down to
// pieces too short to pay (their rows, and every row outside a piece, are the chain's).
//
// What a row's shifts are: exact to the tolerance (1e-7 deg per crossing, checked at each piece's
// check rows; between the checks the chain's smoothness is assumed, as for the simulation's
// table), at exactly the inputs they were built for: a request at other inputs rebuilds the
// row's block (a block is some 20 minutes of the time axis), so the fit's every step sees the
// chain's own values to the tolerance, never an extrapolation. The gradients with respect to
// the inputs the fit frees are the chain's (Jets) at every other node, interpolated, and checked
// at the same rows to 1e-4 of their size: enough for the fit's steps and its 1 sigma, at about
// half the Jets (docs/DECISIONS.md). A block carries the gradients of the inputs it was asked
// for (series_mask) and no others: a Jet's cost grows with its slots.
//
// Thread-safe: shift_at may be called from the fit's threads at once; each block is built under
// its own lock (the threads' rows are contiguous, so they seldom wait for one another).
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "simulation/physics_table.hpp"

namespace conescan::calibration {

/// The model's inputs a physics head's crossings depend on: the head's misalignment components,
/// cone-angle bias, tau-ms and threshold; the Earth's horizon-km, horizon-pole-km,
/// horizon-shift-km, radiance-offset-km and radiance-scale-km (forward_model.hpp's order).
inline constexpr std::size_t series_input_count = 10;
using series_inputs = std::array<double, series_input_count>;
/// A set of the inputs, bit i for input i: those whose gradients a sample or a block carries.
using series_mask = std::uint16_t;
inline constexpr series_mask all_series_inputs = (1u << series_input_count) - 1;

/// The chain at one row and set of inputs: the crossings' shifts from the geometric ones (rad,
/// Earth-in and Earth-out), with `gradient` their derivatives with respect to the inputs (0 for
/// an input that is NaN, absent, and for one whose gradient was not asked), and the geometric chord
/// (rad). ok false: the chain gave no ok crossings (its status is the row's, found again when the
/// row runs the chain).
struct series_sample {
  bool ok = false;
  std::array<double, 2> shift{};
  std::array<series_inputs, 2> gradient{};
  double chord_rad = 0;
};

/// Evaluates the chain at internal row `row` for `inputs`, with the gradients of the inputs in
/// `gradient` (none: 0).
using series_evaluator = std::function<series_sample(std::size_t row, const series_inputs& inputs,
                                                     series_mask gradient)>;

struct physics_time_series_settings {
  double block_s = 1200;  ///< the time axis's first pieces, at most this long
  int nodes = 16;         ///< Chebyshev-Lobatto points a piece takes the chain at
  int checks = 4;         ///< rows between nodes where the piece is checked
  /// 1e-7 deg per crossing: the simulation's table's build tolerance, the same rule
  double tolerance_rad = scene::physics_table_tolerance_rad;
  double gradient_tolerance = 1e-4;  ///< of the largest size of each derivative at the nodes
};

class physics_time_series {
 public:
  /// Over rows at `times_s` (strictly increasing: the caller checks, series_times_usable).
  physics_time_series(std::vector<double> times_s, physics_time_series_settings settings = {});
  ~physics_time_series();

  /// Row `row`'s shifts, and the gradients of the inputs in `gradient`, at `inputs`, building its
  /// block there first where it was built for other inputs or without one of those gradients
  /// (a block built with more serves fewer). False: the row is the chain's
  /// (outside every piece that passed its checks, or its geometric chord outside those the
  /// piece's nodes and checks saw).
  bool shift_at(std::size_t row, const series_inputs& inputs, series_mask gradient,
                double chord_rad, const series_evaluator& evaluate, series_sample& out) const;

  /// The chain evaluations the builds have made so far (for the benchmark and the tests).
  std::size_t evaluations() const noexcept { return evaluations_.load(); }
  /// The rows shift_at has served so far.
  std::size_t served() const noexcept { return served_.load(); }

 private:
  struct piece;
  struct block;
  struct node_row {
    std::size_t row;
    bool gradient;  ///< a node the gradients are interpolated through
  };
  static void interpolate(const piece& p, double t_s, bool gradient, series_sample& out);
  void build(block& b, const series_inputs& inputs, series_mask gradient,
             const series_evaluator& evaluate) const;
  void build_piece(block& b, std::size_t first, std::size_t end, const series_inputs& inputs,
                   series_mask gradient, const series_evaluator& evaluate) const;
  std::vector<node_row> node_rows(const piece& p) const;
  bool take_nodes(piece& p, const std::vector<node_row>& rows, const series_inputs& inputs,
                  series_mask gradient, const series_evaluator& evaluate) const;
  bool checks_pass(piece& p, const std::vector<node_row>& rows, const series_inputs& inputs,
                   series_mask gradient, const series_evaluator& evaluate) const;

  std::vector<double> times_s_;
  physics_time_series_settings settings_;
  std::vector<std::unique_ptr<block>> blocks_;
  std::vector<std::size_t> block_first_;  // each block's first row
  mutable std::atomic<std::size_t> evaluations_{0};
  mutable std::atomic<std::size_t> served_{0};
};

/// True when times are strictly increasing: a time series can follow them.
bool series_times_usable(const std::vector<double>& times_s) noexcept;

}  // namespace conescan::calibration
