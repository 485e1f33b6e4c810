// Error-budget statistics of a run: per head and for the system solution (issue 5, --summary).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/simulation.hpp"

namespace conescan::scene {

/// Statistics of one source (a head or the system) over the rows of a run.
struct error_statistics {
  std::uint64_t rows = 0;
  std::array<std::uint64_t, 7> status_counts{};  ///< indexed by conescan::status
  // Over the ok rows only, rad.
  double roll_min = 0, roll_max = 0, roll_sum = 0, roll_sum_squares = 0;
  double pitch_min = 0, pitch_max = 0, pitch_sum = 0, pitch_sum_squares = 0;

  void add(double roll_err, double pitch_err, status state) noexcept;
  std::uint64_t ok_rows() const noexcept { return status_counts[0]; }
  double roll_mean() const noexcept;
  double roll_rms() const noexcept;
  double pitch_mean() const noexcept;
  double pitch_rms() const noexcept;
};

/// Accumulates a run's rows: heads[k] for head k, and the system solution.
struct run_summary {
  std::vector<error_statistics> heads;
  error_statistics system;

  explicit run_summary(std::size_t head_count) : heads(head_count) {}
  void add(const row& r) noexcept;
};

}  // namespace conescan::scene
