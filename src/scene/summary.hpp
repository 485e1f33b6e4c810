// Error-budget statistics of a run: per head and for the system solution (issue 5 --summary,
// issue 7 --runs).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/simulation.hpp"

namespace conescan::scene {

/// Running statistics of one quantity (Welford's update: no cancellation in the variance when
/// the mean is much larger than the spread, as with a bias plus a little noise).
struct running_statistics {
  std::uint64_t count = 0;
  double min = 0, max = 0, mean = 0, m2 = 0;

  void add(double x) noexcept;
  /// Adds the values `other` summarises (Chan, Golub & LeVeque's pairwise update of the mean and
  /// M2): the statistics of both sets, within a few ulps of adding the values one by one.
  void merge(const running_statistics& other) noexcept;
  double rms() const noexcept;  ///< sqrt(mean of squares); NaN when empty
  double std() const noexcept;  ///< sample standard deviation (n - 1); NaN below 2 values
};

/// Statistics of one source (a head or the system) over the rows of a run.
struct error_statistics {
  std::uint64_t rows = 0;
  /// Rows per status, indexed by status_index (in the order of all_statuses).
  std::array<std::uint64_t, status_count> status_counts{};
  running_statistics roll, pitch;  ///< rad, over the ok rows only

  void add(double roll_err, double pitch_err, status state) noexcept;
  void merge(const error_statistics& other) noexcept;
  std::uint64_t ok_rows() const noexcept { return status_counts[status_index(status::ok)]; }
};

/// Accumulates a run's rows: heads[k] for head k, and the system solution.
struct run_summary {
  std::vector<error_statistics> heads;
  error_statistics system;

  explicit run_summary(std::size_t head_count) : heads(head_count) {}
  void add(const row& r) noexcept;
  /// `other` must have as many heads.
  void merge(const run_summary& other) noexcept;
};

}  // namespace conescan::scene
