// Error-budget statistics of a run: per head and for the system solution (--summary,
// --runs).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "simulation/simulation.hpp"

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

/// Rows of one chunk of a summary. conescan-sim sums the statistics within chunks of
/// this many consecutive rows of one run (Welford) and merges the chunks in order (Chan), whatever
/// its --threads, so that a summary is the same bits with any number of threads. Every other
/// runner of a summary (the Python module, the tests) accumulates through chunked_summary to give
/// those same bits: a row-by-row Welford over a whole run differs in the last digits.
inline constexpr std::size_t summary_chunk_rows = 2048;

/// `Summary` (run_summary, budget_summary) accumulated chunk by chunk as conescan-sim does. Call
/// end_run() after each run's last row (a chunk never spans two runs); total() then holds the
/// rows added so far.
template <class Summary>
class chunked_summary {
 public:
  /// `empty`: a summary of no rows, of the right shape.
  explicit chunked_summary(const Summary& empty) : empty_(empty), total_(empty), chunk_(empty) {}

  template <class Row>
  void add(const Row& r) {
    chunk_.add(r);
    if (++chunk_rows_ == summary_chunk_rows) end_chunk();
  }
  void end_run() { end_chunk(); }
  const Summary& total() const noexcept { return total_; }

 private:
  void end_chunk() {
    if (chunk_rows_ == 0) return;
    total_.merge(chunk_);
    chunk_ = empty_;
    chunk_rows_ = 0;
  }

  Summary empty_, total_, chunk_;
  std::size_t chunk_rows_ = 0;
};

}  // namespace conescan::scene
