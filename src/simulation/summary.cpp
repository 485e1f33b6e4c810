#include "simulation/summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace conescan::scene {

void running_statistics::add(double x) noexcept {
  ++count;
  if (count == 1) min = max = x;
  min = std::min(min, x);
  max = std::max(max, x);
  const double delta = x - mean;
  mean += delta / static_cast<double>(count);
  m2 += delta * (x - mean);
}

void running_statistics::merge(const running_statistics& other) noexcept {
  if (other.count == 0) return;
  if (count == 0) {
    *this = other;
    return;
  }
  const auto n_a = static_cast<double>(count), n_b = static_cast<double>(other.count);
  const double n = n_a + n_b;
  const double delta = other.mean - mean;
  // mean + delta n_b / n rather than (n_a mean + n_b mean_b) / n: no cancellation when the two
  // means are large and close (a bias plus a little noise).
  mean += delta * (n_b / n);
  m2 += other.m2 + delta * delta * (n_a * n_b / n);
  count += other.count;
  min = std::min(min, other.min);
  max = std::max(max, other.max);
}

double running_statistics::rms() const noexcept {
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(mean * mean + m2 / static_cast<double>(count));
}

double running_statistics::std() const noexcept {
  if (count < 2) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(m2 / static_cast<double>(count - 1));
}

void error_statistics::add(double roll_err, double pitch_err, status state) noexcept {
  ++rows;
  ++status_counts[status_index(state)];
  if (state != status::ok) return;
  roll.add(roll_err);
  pitch.add(pitch_err);
}

void error_statistics::merge(const error_statistics& other) noexcept {
  rows += other.rows;
  for (std::size_t s = 0; s < status_counts.size(); ++s) status_counts[s] += other.status_counts[s];
  roll.merge(other.roll);
  pitch.merge(other.pitch);
}

void run_summary::merge(const run_summary& other) noexcept {
  for (std::size_t k = 0; k < heads.size(); ++k) heads[k].merge(other.heads[k]);
  system.merge(other.system);
}

void run_summary::add(const row& r) noexcept {
  for (std::size_t k = 0; k < heads.size(); ++k)
    heads[k].add(r.heads[k].roll_err_rad, r.heads[k].pitch_err_rad, r.heads[k].state);
  system.add(r.roll_err_rad, r.pitch_err_rad, r.state);
}

}  // namespace conescan::scene
