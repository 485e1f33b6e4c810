// The true attitude as a table (MODEL §10): a CSV of a time column and either 3-2-1 Euler angles
// orbital -> body (MODEL §2) or a quaternion inertial -> body, as star trackers give it.
//
// The header names the columns (blanks around names allowed; any order; each once):
//  - the time, one of: t_s (seconds from the scene's epoch); utc (ISO 8601 UTC,
//    YYYY-MM-DDThh:mm:ss[.f][Z] or YYYY-DDDThh:mm:ss[.f][Z], leap seconds through ERFA); gps_week
//    and gps_s (GPS weeks since 1980-01-06T00:00:00 GPS, counted on, not modulo 1024, and the
//    seconds of the week in [0, 604800); GPS = TAI - 19 s). Absolute times become seconds from
//    the scene's epoch (attitude_csv_options::epoch); two kinds of time are refused;
//  - the attitude, one of: roll_deg, pitch_deg, yaw_deg (3-2-1 angles orbital -> body); or q_w,
//    q_x, q_y, q_z, a unit quaternion (scalar q_w = cos(phi/2), vector (q_x, q_y, q_z) =
//    e sin(phi/2)), scalar first or last as the columns are ordered: the names say which is the
//    scalar. Mixed angle and quaternion columns, other columns, are refused.
// Then one row per time, times strictly increasing, every field a finite number (utc: an epoch);
// blank lines skipped; "\r\n" ends accepted. Refused with file, line and column: anything else,
// a quaternion whose norm is not 1 within attitude_csv_quaternion_tolerance (it is normalised
// when within), a file of no rows.
//
// Quaternion convention (the same as an AEM's A2B, aem.hpp): the quaternion transforms
// coordinates from the inertial frame to the body frame, v_body = A(q) v_inertial with
// A(q) = (q_w^2 - |q_v|^2) I + 2 q_v q_v^T - 2 q_w [q_v x] (Shuster's attitude matrix; the
// body axes are the inertial ones turned by phi about e). In rotation.hpp's active Hamilton
// terms body <- inertial = R(conj q). A table whose quaternions go body -> inertial is this one
// with (q_x, q_y, q_z) negated. The inertial frame is the option --attitude-frame's (the
// table does not say it); q and -q are one attitude.
//
// Interpolation. Angles: linear in each angle between the two rows around t, each angle's
// change taken the short way round (within +-180 deg, so 179 -> -179 passes through 180). Chosen
// over the geodesic (slerp) of the two rotations because the file holds angles: a row-to-row ramp
// of the angles is what a user writing them means, and that it reproduces exactly. The two
// differ at second order in the angles' changes: 8.7e-3 deg at the midpoint of (roll, pitch, yaw)
// = (0, 2, 2) -> (2, 0, 2) deg, 3.8e-5 deg for 0.1-deg changes (measured, docs/SOURCES.md).
// Quaternions: the geodesic (slerp) between the two rows around t, the shorter way (signs made
// continuous), exact at the rows; an AEM of the same samples with INTERPOLATION LINEAR gives the
// same rotation (tests/test_attitude_csv.cpp). Sample the attitude finely enough that its own
// curvature between rows is below the accuracy wanted: as an AEM's, each interval's
// interpolation error is estimated when the table is read (at the interval's midpoint, the
// rotation between the interpolant used and the quadratic through the two rows and the next
// one, or the one before at the end), and check_coverage refuses a scene's span where the worst
// estimate is above the angles' tolerance (1e-6 deg; --interpolation-tolerance-deg raises it).
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
