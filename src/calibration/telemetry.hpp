// Telemetry as the calibration reads it (MODEL §11): CSV with a header line, a row per time,
// its time and for each head K of the scene hK_chord_deg and hK_phase_deg (deg); every other
// column is ignored. conescan-sim's own CSV (MODEL §9) is one valid input.
//
// The time, one of: t_s (seconds from the scene's epoch); utc (ISO 8601 UTC, as
// time_scales.hpp's parse_epoch reads it); gps_week and gps_s (GPS week counted on from
// 1980-01-06 and seconds of the week). The engine knows no calendar (it may not include the
// sources library, docs/ARCHITECTURE.md): absolute time stamps are turned into seconds from the
// scene's epoch by the telemetry_time_stamps the caller gives, which scene_calibration makes from
// the scene (scene_time_stamps, scene_fit.hpp) with ERFA's leap seconds. Without them an
// absolute time column is refused.
//
// Rules, each refused with the file, line and column (exit 2 in the programs):
// - the header: columns separated by commas, no quotes; one time (t_s, utc, or gps_week and
//   gps_s: two kinds are refused) and each head's chord and phase columns present once; the
//   telemetry's head count (the largest K with an hK_chord_deg or
//   hK_phase_deg column) equal to the scene's;
// - each row: as many fields as the header; t_s a finite number, strictly increasing from row to
//   row, within the scene's span when the caller gives it (telemetry_time_stamps::span); a chord a
//   finite number in (0, 360), a phase any finite number; numbers in the form std::from_chars reads
//   (an optional minus sign, digits, point, exponent: no spaces, no '+', no hex, no inf);
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
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
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

/// The span of time the rows must lie in, seconds from the scene's epoch: the scene's own, so that
/// telemetry of another time (GPS weeks written modulo 1024, 19.6 years early; another day's
/// file) is refused instead of fitted to the scene's geometry of another time.
struct telemetry_span {
  double first_s = 0;
  double last_s = 0;
  std::string set_by;  ///< what sets it, for the message: "--duration-s", "--orbits"
};

/// Absolute time stamps as seconds from the scene's epoch (top of file), and the span the rows
/// must lie in (none: any time). An error's message is placed at the row's time field by the
/// reader.
struct telemetry_time_stamps {
  std::function<checked<double>(std::string_view utc)> from_utc;
  std::function<checked<double>(double gps_week, double gps_seconds)> from_gps;
  std::optional<telemetry_span> span;
};

/// Reads telemetry for a scene of `head_count` heads from `in`; `file_name` names it in errors
/// (option "telemetry"). `stamps` turns utc and GPS times into t_s.
checked<telemetry> read_telemetry(std::istream& in, const std::string& file_name,
                                  std::size_t head_count, const telemetry_time_stamps& stamps = {});

/// The same from the file at `path`.
checked<telemetry> read_telemetry_file(const std::string& path, std::size_t head_count,
                                       const telemetry_time_stamps& stamps = {});

}  // namespace conescan::calibration
