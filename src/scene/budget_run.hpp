// The error budget's run (--budget): every source's scene (budget.hpp) in lock step, one time
// step at a time, with the sum of the single sources to judge linearity. conescan-sim's CSV and
// summary (src/cli/csv_rows.hpp) and the Python module read it through
// csv_columns.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/budget.hpp"
#include "scene/simulation.hpp"
#include "scene/summary.hpp"

namespace conescan::scene {

/// One time step of the budget: each source's row (rad, SI), and the sum of the single sources'
/// system errors (every source but "all"); its state is ok when each of theirs is, else none.
struct budget_row {
  std::vector<row> sources;
  double roll_sum_rad = 0;
  double pitch_sum_rad = 0;
  status sum_state = status::none;
};

class budget_run {
 public:
  /// `sources` as budget_sources gives them (validated), the last one "all".
  explicit budget_run(const std::vector<budget_source>& sources);

  /// Time steps (every source has the same).
  std::uint64_t rows() const noexcept { return sims_.front().rows(); }
  /// A row with room for every source and head: compute() then never allocates.
  budget_row make_row() const;
  /// Fills `out` for time step k.
  void compute(std::uint64_t k, budget_row& out) const noexcept;
  /// The sum of the single sources from `out.sources` (already computed): what compute() does
  /// after the sources' rows. The campaign runner computes each source's rows in blocks
  /// (simulation::compute_rows) and sums here, so both keep one rule.
  void sum_single_sources(budget_row& out) const noexcept;
  /// The sources' simulations, in the order of `sources` (for block computation).
  const std::vector<simulation>& simulations() const noexcept { return sims_; }

 private:
  std::vector<simulation> sims_;
  std::vector<bool> single_;  // a single source (summed), not "all"
};

/// The budget's statistics: one per source, then the sum's.
struct budget_summary {
  std::vector<error_statistics> sources;
  error_statistics sum;

  explicit budget_summary(std::size_t source_count) : sources(source_count) {}
  void add(const budget_row& r) noexcept;
  /// `other` must have as many sources (Chan's merge, summary.hpp).
  void merge(const budget_summary& other) noexcept;
};

}  // namespace conescan::scene
