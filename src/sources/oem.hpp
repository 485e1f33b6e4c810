// CCSDS Orbit Ephemeris Message (OEM, CCSDS 502.0-B-3), KVN, versions 1 to 3: read, turned
// inertial, interpolated, with an estimate of the interpolation error (MODEL §10).
//
// Read: the header (CCSDS_OEM_VERS first; CREATION_DATE, ORIGINATOR mandatory), META blocks,
// any number of segments, COMMENT lines anywhere, covariance blocks (COVARIANCE_START/STOP)
// skipped, data lines "epoch x y z vx vy vz [ax ay az]" in km and km/s (accelerations read and
// ignored). Values are case-insensitive ("Earth", "Lagrange"); keywords are not.
// Accepted: CENTER_NAME EARTH; TIME_SYSTEM UTC, TAI, TT, GPS; REF_FRAME EME2000, GCRF, ICRF,
// TEME, TOD (kept as they are: the scene rotates them into TOD, simulation/truth_source.hpp) or
// ITRF* (turned inertial, CIRS, with ERFA's Earth rotation angle and v + w x r, polar motion
// neglected: earth_rotation.hpp).
// Refused, with file, line and keyword or value: an unknown or repeated keyword, a missing
// mandatory one, any other centre, frame or time system, a malformed epoch or number, a data
// line of the wrong length, epochs not strictly increasing in a segment, a segment without
// data or whose usable span misses its data, more data lines kept than the limit.
//
// Interpolation, within one segment only, as its INTERPOLATION and INTERPOLATION_DEGREE say
// (absent: oem_default_method, oem_default_degree): on the samples nearest the interval that
// holds t (ephemeris_interpolation.hpp), in the inertial frame:
//  LAGRANGE d: positions and velocities, each through d + 1 samples;
//  HERMITE d:  positions through ceil((d + 1) / 2) samples and their velocities (a polynomial of
//              degree >= d); the velocity is its derivative;
//  LINEAR:     positions and velocities through the 2 samples around t.
// A segment with fewer samples uses all it has. Error estimate: the difference from the same
// interpolation with the next nearest sample added (or, when the segment has no more, from the
// one with the farthest removed: larger, so conservative), at each interval's midpoint.
#pragma once

#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "sources/cartesian_state.hpp"
#include "sources/earth_orientation.hpp"
#include "sources/sampled_segment.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// Without INTERPOLATION and INTERPOLATION_DEGREE (docs/SOURCES.md: Hermite of degree 7 takes 4
/// samples, the narrowest window for that degree, and uses the velocities every OEM carries).
inline constexpr interpolation_method oem_default_method = interpolation_method::hermite;
inline constexpr int oem_default_degree = 7;

/// Data lines an OEM reader keeps at most: 2^21 (a day at 25 Hz, 24 days at 1 Hz), 136 MiB of
/// states with their error estimates. A larger file is read if a span limits what is kept.
inline constexpr std::size_t oem_max_states = std::size_t{1} << 21;

/// The direction accuracy conescan's angles need from an ephemeris: 1e-6 deg.
inline constexpr double default_max_interpolation_angle_rad = 1e-6 * std::numbers::pi / 180;

struct oem_read_options {
  /// Keep only the states that interpolation over this span needs (else all of them).
  std::optional<time_span> span;
  std::size_t max_states = oem_max_states;
  /// UT1 - UTC for ITRF frames (s); 0 without IERS data (earth_rotation.hpp states the cost).
  double ut1_minus_utc_s = 0;
  /// The Earth's orientation for ITRF frames (--eop; not owned), used instead of
  /// ut1_minus_utc_s: each state turned with its day's UT1 - UTC and pole; a state outside the
  /// table's days is refused, naming its line and the days the table covers.
  const earth_orientation* eop = nullptr;
};

/// One segment: inertial states (m, m/s) as read, the frame and time system its META named.
struct oem_segment : sampled_segment<cartesian_state> {
  std::string ref_frame;  ///< as written (ITRF* states are already turned inertial)
  time_scale time_system = time_scale::utc;
};

/// A state with the estimate of its interpolation error.
struct interpolated_state {
  cartesian_state state;
  interval_error estimate;
};

/// The interpolated state at tau seconds from the segment's reference, in interval k, with the
/// error estimate there (used by state_at and to fill the segment's estimates).
interpolated_state interpolate_oem(const oem_segment& s, std::size_t k, double tau) noexcept;

/// An OEM once read: its segments, usable_start() (MODEL §10: without --epoch the scene's epoch),
/// usable_stop(), worst_error(t0, t1), path() (sampled_segment.hpp), and:
class oem_ephemeris : public sampled_file<oem_segment, interpolate_oem> {
 public:
  /// Before any row: success when every time of [t0, t1] can be interpolated and, given
  /// max_angle_rad, when no interval meeting the span has an error estimate above it and
  /// segments that overlap there agree within it (where they overlap the later serves: two
  /// orbits for one time are refused, not chosen between silently). Errors name the file, the
  /// data line, the time and the figure.
  checked<void> check_coverage(
      const instant& t0, const instant& t1,
      std::optional<double> max_angle_rad = default_max_interpolation_angle_rad) const;

  /// The inertial state at t, from the segment that serves it (the last whose usable span holds
  /// it); refused outside every usable span. With the estimate of the interval that holds t (at
  /// its midpoint, computed when the file was read).
  checked<interpolated_state> state_at(const instant& t) const { return value_at(t); }

 private:
  friend checked<oem_ephemeris> read_oem(const std::string& path, const oem_read_options& options);
  using sampled_file::sampled_file;
};

/// Reads an OEM (top of file); every refusal is a diagnostic naming file and line.
checked<oem_ephemeris> read_oem(const std::string& path, const oem_read_options& options = {});

}  // namespace conescan::sources
