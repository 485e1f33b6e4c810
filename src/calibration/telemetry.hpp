// Telemetry as the calibration reads it (MODEL §11): CSV with a header line, a row per time, its
// time and for each head K of the scene hK_chord_deg and hK_phase_deg (deg); every other column
// is ignored, and conescan-sim's own CSV (MODEL §9) is one valid input. The time is t_s (seconds
// from the scene's epoch), or utc, or gps_week and gps_s: the engine knows no calendar (it may not
// include the sources library, docs/ARCHITECTURE.md), so absolute times become t_s through the
// telemetry_time_stamps the caller gives (scene_time_stamps, scene_fit.hpp); without them an
// absolute time column is refused, and a row outside the scene's span when the caller gives it
// (telemetry_time_stamps::span). A head's `nan` leaves that head out of that row, counted.
// Anything else that is not as the format says is refused with the file, line and column (exit 2
// in the programs); at most max_telemetry_measurements are read (rows times heads, 40 bytes each:
// about 0.6 GB with a fit's own at the limit). Every rule: docs/CALIBRATION.md, "Files".
#pragma once

#include <cstddef>
#include <functional>
#include <istream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
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

/// Telemetry as columns in memory (conescan.fit's arrays): each column's name and its values, the
/// text columns (utc) before the numeric ones, every column as long as the first. The values are
/// borrowed: they must outlive the reading.
struct telemetry_columns {
  std::vector<std::pair<std::string, std::vector<std::string>>> texts;
  std::vector<std::pair<std::string, std::span<const double>>> numbers;
  /// Rows: the length of the first column (0 without columns).
  std::size_t row_count() const noexcept;
};

/// Reads telemetry columns exactly as read_telemetry reads the CSV they make (the names as the
/// header, one line per row, a number as its shortest round-trip text, NaN as nan): the same
/// checks and the same messages, their line and column those of that CSV, `name` in the place of
/// the file's name. Without building the text. Columns of different lengths are the caller's to
/// refuse (read: up to the shortest).
checked<telemetry> read_telemetry_columns(const telemetry_columns& columns, const std::string& name,
                                          std::size_t head_count,
                                          const telemetry_time_stamps& stamps = {});

}  // namespace conescan::calibration
