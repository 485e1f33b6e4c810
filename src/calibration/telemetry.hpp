// Telemetry as the calibration reads it (MODEL §11): CSV with a header line, a row per time,
// t_s and for each head K of the scene hK_chord_deg and hK_phase_deg (deg); every other column
// is ignored. conescan-sim's own CSV (MODEL §9) is one valid input.
//
// Rules, each refused with the file, line and column (exit 2 in the programs):
// - the header: columns separated by commas, no quotes; t_s and each head's chord and phase
//   columns present once; the telemetry's head count (the largest K with an hK_chord_deg or
//   hK_phase_deg column) equal to the scene's;
// - each row: as many fields as the header; t_s a finite number, strictly increasing from row to
//   row; a chord a finite number in (0, 360), a phase any finite number; numbers in the form
//   std::from_chars reads (an optional minus sign, digits, point, exponent: no spaces, no '+',
//   no hex, no inf);
// - the text `nan` (what conescan-sim writes for a head that could not measure: its status says
//   why) for a head's chord or phase: that head is left out of that row, and counted; any other
//   non-finite or non-numeric text is an error. A head's status column, when present, is not
//   read: the numbers decide (a head whose inversion failed, status fold or ambiguous, still
//   measured its chord and phase);
// - an empty file, a header without rows, an empty line, a line longer than 1 MiB.
// A CR before the line end and a UTF-8 byte-order mark at the start are accepted.
//
// Bounded memory: at most max_telemetry_measurements (rows times the scene's heads, nan ones
// included; 6 million: 34.7 days of two heads at 1 Hz) are read; more is refused, with the line
// where the limit was passed. The reader keeps one line at a time and the measurements (40 bytes
// each; 24 for a nan one); a fit adds about as much again, whatever the length (the model's
// geometry of each row, one byte per measurement: docs/CALIBRATION.md,
// bench/calibration_speed.cpp), so about 0.6 GB at the limit.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "calibration/forward_model.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

inline constexpr std::size_t max_telemetry_measurements = 6'000'000;
inline constexpr std::size_t max_telemetry_line_bytes = std::size_t{1} << 20;

struct telemetry {
  std::string file;  ///< the file it was read from (errors about a row name it and the line)
  std::size_t row_count = 0;
  std::vector<observation> observations;      ///< row by row, heads in order within a row
  std::vector<std::size_t> skipped_per_head;  ///< rows where the head's chord or phase is nan
  /// Each of those: its row, time and head (what a fit with --intrusions asks the scene about:
  /// was the head blinded there?). Counted with the observations against the measurement limit.
  std::vector<telemetry_sample> unmeasured;
};

/// Reads telemetry for a scene of `head_count` heads from `in`; `file_name` names it in errors
/// (option "telemetry").
checked<telemetry> read_telemetry(std::istream& in, const std::string& file_name,
                                  std::size_t head_count);

/// The same from the file at `path`.
checked<telemetry> read_telemetry_file(const std::string& path, std::size_t head_count);

}  // namespace conescan::calibration
