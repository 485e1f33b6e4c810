// The true attitude as a table (MODEL §10): a CSV of a time column (t_s, utc, or gps_week and
// gps_s) and either 3-2-1 Euler angles orbital -> body (MODEL §2) or a quaternion inertial -> body
// as star trackers give it (scalar first or last: the column names say which), read and
// interpolated at any time within its rows. Times strictly increasing, every field a finite number
// (utc: an epoch), blank lines skipped, "\r\n" accepted; refused with file, line and column:
// anything else, a quaternion whose norm is not 1 within attitude_csv_quaternion_tolerance (it is
// normalised when within), a file of no rows.
//
// The quaternion transforms coordinates from the inertial frame (--attitude-frame's) to the body
// frame, as an AEM's A2B (aem.hpp): in rotation.hpp's active Hamilton terms body <- inertial =
// R(conj q); q and -q are one attitude. Interpolation, exact at the rows: angles linear in each
// angle, the short way round (a ramp of the angles, as the file holds angles); quaternions on the
// geodesic (slerp). Each interval's interpolation error is estimated when the table is read, and
// check_coverage refuses a scene's span where the worst estimate is above the angles' tolerance
// (1e-6 deg; --interpolation-tolerance-deg raises it). The columns, the conventions and how far
// the two interpolations differ: docs/SOURCES.md, "Attitude tables".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sources/rotation.hpp"
#include "sources/time_scales.hpp"
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

/// How far a quaternion's norm may be from 1 (the AEM reader's tolerance): 1e-3, six digits
/// written per component keep the norm within 2e-6; beyond it the row is not a rotation.
inline constexpr double attitude_csv_quaternion_tolerance = 1e-3;

/// What the table holds.
enum class attitude_table_kind { angles, quaternions };

/// Which column gives each row's time.
enum class attitude_time_column { t_s, utc, gps };

struct attitude_csv_options {
  /// The scene's t = 0: needed for utc and GPS times (without it they are refused).
  std::optional<instant> epoch;
  std::size_t max_rows = attitude_csv_max_rows;
};

class attitude_table {
 public:
  const std::string& path() const noexcept { return path_; }
  std::size_t rows() const noexcept { return t_s_.size(); }
  double first_t_s() const noexcept { return t_s_.front(); }
  double last_t_s() const noexcept { return t_s_.back(); }
  attitude_table_kind kind() const noexcept { return kind_; }
  attitude_time_column time_column() const noexcept { return time_; }
  /// Quaternion tables: true when the header put q_w before q_x.
  bool scalar_first() const noexcept { return scalar_first_; }

  /// Before any row of the scene: success when [t0_s, t1_s] lies within the table's times and,
  /// given max_angle_rad, no interval meeting it has an interpolation error estimate above it
  /// (the message names the estimate, the row that starts the interval and the rows' spacing).
  checked<void> check_coverage(double t0_s, double t1_s,
                               std::optional<double> max_angle_rad = std::nullopt) const;

  /// The interpolation error estimate of interval k, [t_s(k), t_s(k + 1)], rad (0 for a table
  /// of one row).
  double interval_error_rad(std::size_t k) const noexcept {
    return k < errors_rad_.size() ? static_cast<double>(errors_rad_[k]) : 0.0;
  }

  /// The interpolated angles at t_s (top of file); refused outside the table's times and for a
  /// quaternion table.
  checked<attitude_angles> angles_at(double t_s) const;

  /// The rotation body <- inertial at t_s (rotation.hpp: v_body = apply(rotation_matrix(q),
  /// v_inertial)), the geodesic between rows; refused outside the table's times and for an
  /// angle table.
  checked<quaternion> body_from_inertial_at(double t_s) const;

 private:
  friend checked<attitude_table> read_attitude_csv(const std::string& path,
                                                   const attitude_csv_options& options);
  friend class attitude_csv_reader;
  checked<std::size_t> interval(double t_s) const;
  void estimate_errors();  // errors_rad_ from the rows, once read

  std::string path_;
  attitude_table_kind kind_ = attitude_table_kind::angles;
  attitude_time_column time_ = attitude_time_column::t_s;
  bool scalar_first_ = true;
  std::vector<double> t_s_;
  std::vector<attitude_angles> angles_;         // rad, as written (not wrapped)
  std::vector<quaternion> body_from_inertial_;  // unit, signs continuous from row to row
  std::vector<std::uint64_t> lines_;            // the file's line of each row, for messages
  std::vector<float> errors_rad_;               // errors_rad_[k]: interval [t_s_[k], t_s_[k + 1]]
};

checked<attitude_table> read_attitude_csv(const std::string& path,
                                          const attitude_csv_options& options = {});

}  // namespace conescan::sources
