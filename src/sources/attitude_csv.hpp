// The true attitude as a table (MODEL §10): a CSV "t_s,roll_deg,pitch_deg,yaw_deg" of 3-2-1 Euler
// angles orbital -> body (MODEL §2), t_s in seconds from the scene's epoch.
//
// The file: that header line exactly (blanks around the names allowed), then one row per time,
// t_s strictly increasing, four finite numbers a row; blank lines are skipped; "\r\n" ends
// accepted. Refused with file, line and column: anything else, and a file of no rows.
//
// Interpolation: linear in each angle between the two rows around t, each angle's change taken
// the short way round (within +-180 deg, so 179 -> -179 passes through 180). Chosen over the
// geodesic (slerp) of the two rotations because the file holds angles: a row-to-row ramp of the
// angles is what a user writing them means, and that it reproduces exactly. The two differ at
// second order in the angles' changes: 8.7e-3 deg at the midpoint of (roll, pitch, yaw) = (0, 2,
// 2) -> (2, 0, 2) deg, 3.8e-5 deg for 0.1-deg changes (measured, docs/SOURCES.md): sample the
// attitude finely enough that its own curvature between rows is below the accuracy wanted.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "text/diagnostic.hpp"

namespace conescan::sources {

/// 3-2-1 angles orbital -> body (rad): C = R1(roll) R2(pitch) R3(yaw), as
/// conescan::dcm_body_from_orbit takes them.
struct attitude_angles {
  double roll_rad = 0;
  double pitch_rad = 0;
  double yaw_rad = 0;
};

/// Rows an attitude table keeps at most (32 MiB): larger files are refused, naming the limit.
inline constexpr std::size_t attitude_csv_max_rows = std::size_t{1} << 20;

class attitude_table {
 public:
  const std::string& path() const noexcept { return path_; }
  std::size_t rows() const noexcept { return t_s_.size(); }
  double first_t_s() const noexcept { return t_s_.front(); }
  double last_t_s() const noexcept { return t_s_.back(); }

  /// Before any row of the scene: nullopt when [t0_s, t1_s] lies within the table's times.
  checked<void> check_coverage(double t0_s, double t1_s) const;

  /// The interpolated angles at t_s (top of file); refused outside the table's times.
  checked<attitude_angles> angles_at(double t_s) const;

 private:
  friend checked<attitude_table> read_attitude_csv(const std::string& path, std::size_t max_rows);
  std::string path_;
  std::vector<double> t_s_;
  std::vector<attitude_angles> angles_;  // rad, as written (not wrapped)
};

checked<attitude_table> read_attitude_csv(const std::string& path,
                                          std::size_t max_rows = attitude_csv_max_rows);

}  // namespace conescan::sources
