// conescan-fit --residuals FILE: every measurement's residuals at a converged fit's solution, one
// CSV row each, for scripts/plot-fit.py (residuals against time and latitude, per head).
//
// Columns: t_s, row (the telemetry's, 0-based after the header), head (1-based), lat_deg (the
// satellite's geocentric latitude), chord_residual_deg and phase_residual_deg (measured minus
// predicted; nan for a measurement the model cannot predict at the solution), normalised
// (sqrt(s / (chi2/dof)), as the outliers are judged), fitted (1, or 0 when left out). Numbers
// are the shortest round-trip text; a month of two heads at 1 Hz is about 0.5 GB.
#pragma once

#include <string>

#include "calibration/estimator.hpp"
#include "cli/output_sink.hpp"
#include "text/diagnostic.hpp"

namespace conescan::cli {

class residual_csv {
 public:
  /// Opens (creates or truncates) the file and writes the header. Error: the file cannot be
  /// opened (option "residuals").
  static checked<residual_csv> open(const std::string& path);
  residual_csv(residual_csv&&) noexcept;
  residual_csv& operator=(residual_csv&&) = delete;
  ~residual_csv();

  void write(const calibration::residual_row& r, double latitude_deg) noexcept;
  /// Writes what is buffered and closes the file. Error: a write failed (option "residuals").
  checked<void> finish();

 private:
  residual_csv(int fd, std::string path);
  int fd_ = -1;
  std::string path_;
  output_sink sink_;
};

}  // namespace conescan::cli
