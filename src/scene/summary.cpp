#include "scene/summary.hpp"

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

void run_summary::add(const row& r) noexcept {
  for (std::size_t k = 0; k < heads.size(); ++k)
    heads[k].add(r.heads[k].roll_err_rad, r.heads[k].pitch_err_rad, r.heads[k].state);
  system.add(r.roll_err_rad, r.pitch_err_rad, r.state);
}

}  // namespace conescan::scene
