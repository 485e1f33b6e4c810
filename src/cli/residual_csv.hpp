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
#include "text/output_file.hpp"

namespace conescan::cli {

// Written through text::output_file: a regular file is replaced whole only by finish(), a
// device or FIFO written directly, anything else refused; a fit that fails leaves the path as it
// was, with no temporary file.
class residual_csv {
 public:
  /// Checks the path and prepares to write it (text::output_file::open), and the header. Error:
  /// the path cannot be written (option "residuals", errno's text).
  static checked<residual_csv> open(const std::string& path);

  void write(const calibration::residual_row& r, double latitude_deg) noexcept;
  /// Writes what is buffered and commits the file. Error: a write failed (option "residuals").
  checked<void> finish();

 private:
  explicit residual_csv(text::output_file file);
  void pass_on() noexcept;  // the buffer's rows to the file, past a threshold

  text::output_file file_;
  output_sink sink_{-1};  // a buffer of whole rows, handed on in blocks
  checked<void> written_;
};

}  // namespace conescan::cli
