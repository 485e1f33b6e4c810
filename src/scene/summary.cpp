#include "scene/summary.hpp"

#include <cmath>
#include <limits>

namespace conescan::scene {

void error_statistics::add(double roll_err, double pitch_err, status state) noexcept {
  ++rows;
  ++status_counts[static_cast<std::size_t>(state)];
  if (state != status::ok) return;
  if (ok_rows() == 1) {
    roll_min = roll_max = roll_err;
    pitch_min = pitch_max = pitch_err;
  }
  roll_min = std::min(roll_min, roll_err);
  roll_max = std::max(roll_max, roll_err);
  pitch_min = std::min(pitch_min, pitch_err);
  pitch_max = std::max(pitch_max, pitch_err);
  roll_sum += roll_err;
  roll_sum_squares += roll_err * roll_err;
  pitch_sum += pitch_err;
  pitch_sum_squares += pitch_err * pitch_err;
}

namespace {
double mean_of(double sum, std::uint64_t n) {
  return n ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

double error_statistics::roll_mean() const noexcept { return mean_of(roll_sum, ok_rows()); }
double error_statistics::pitch_mean() const noexcept { return mean_of(pitch_sum, ok_rows()); }
double error_statistics::roll_rms() const noexcept {
  return std::sqrt(mean_of(roll_sum_squares, ok_rows()));
}
double error_statistics::pitch_rms() const noexcept {
  return std::sqrt(mean_of(pitch_sum_squares, ok_rows()));
}

void run_summary::add(const row& r) noexcept {
  for (std::size_t k = 0; k < heads.size(); ++k)
    heads[k].add(r.heads[k].roll_err_rad, r.heads[k].pitch_err_rad, r.heads[k].state);
  system.add(r.roll_err_rad, r.pitch_err_rad, r.state);
}

}  // namespace conescan::scene
