// The error budget's run (--budget): every source's scene (budget.hpp) in lock step, one time
// step at a time, with the sum of the single sources and how far `all` is from it (the sources'
// interaction). conescan-sim's CSV and summary (src/cli/csv_rows.hpp) and the Python module read
// it through csv_columns.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "scene/budget.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary.hpp"

namespace conescan::scene {

/// One time step of the budget: each source's row (rad, SI; a source with a baseline carries its
/// system errors less the baseline's, its heads' crossings as its scene gives them), the sum of
/// the single sources' system errors (every source but "all"; ok when each of theirs is, else
/// none), and the interaction: all − sum (ok when both are, else none). The sources are not
/// independent: the field and the lag act on the same limb, the processing is not linear in the
/// crossings, and what one head's error cancels in the system solution depends on the others';
/// the interaction is what `all` holds beyond the single sources.
struct budget_row {
  std::vector<row> sources;
  double roll_sum_rad = 0;
  double pitch_sum_rad = 0;
  status sum_state = status::none;
  double roll_interaction_rad = 0;
  double pitch_interaction_rad = 0;
  status interaction_state = status::none;
};

class budget_run {
 public:
  /// `sources` as budget_sources gives them (validated), the last one "all"; their physics tables
  /// built on up to `threads` threads (simulation::of).
  explicit budget_run(const std::vector<budget_source>& sources, int threads = 1);

  /// Time steps (every source has the same).
  std::uint64_t rows() const noexcept { return sims_.front().rows(); }
  /// A row with room for every source and head: compute() then never allocates.
  budget_row make_row() const;
  /// Fills `out` for time step k.
  void compute(std::uint64_t k, budget_row& out) const noexcept;
  /// From the sources' own rows in `out.sources` (already computed): each source measured from
  /// its baseline, the sum of the single sources and the interaction; what compute() does after
  /// the sources' rows. The campaign runner computes each source's rows in blocks
  /// (simulation::compute_rows) and combines here, so both keep one rule.
  void combine_sources(budget_row& out) const noexcept;
  /// The sources' simulations, in the order of `sources` (for block computation).
  const std::vector<simulation>& simulations() const noexcept { return sims_; }

 private:
  void subtract_baselines(budget_row& out) const noexcept;

  std::vector<simulation> sims_;
  std::vector<bool> single_;                          // a single source (summed), not "all"
  std::vector<std::optional<std::size_t>> baseline_;  // the source each is measured from
  std::size_t all_ = 0;                               // the index of "all"
};

/// The budget's statistics: one per source, then the sum's, then the interaction's.
struct budget_summary {
  std::vector<error_statistics> sources;
  error_statistics sum;
  error_statistics interaction;

  explicit budget_summary(std::size_t source_count) : sources(source_count) {}
  void add(const budget_row& r) noexcept;
  /// `other` must have as many sources (Chan's merge, summary.hpp).
  void merge(const budget_summary& other) noexcept;
  /// The summary's lines in order: the sources, the sum, the interaction.
  std::size_t lines() const noexcept { return sources.size() + 2; }
  const error_statistics& line(std::size_t k) const noexcept;
  /// Empties it and makes room for `lines` lines (lines() of the next chunk's).
  void reset(std::size_t lines);
};

}  // namespace conescan::scene
