// CCSDS Attitude Ephemeris Message (AEM, CCSDS 504.0-B-1 and -B-2), KVN: read, and interpolated
// on the rotation group into the rotation body <- inertial at any time of its usable spans
// (MODEL §10). Accepted: quaternion segments (QUATERNION_TYPE FIRST or LAST, ATTITUDE_DIR A2B or
// B2A) between an inertial frame (EME2000, GCRF, ICRF, TEME, TOD) and a spacecraft body frame,
// either way round, in UTC, TAI, TT or GPS, quaternions of unit norm within 1e-3 (normalised);
// anything else is refused with the file and line. A CCSDS quaternion transforms coordinates from
// frame A to frame B for A2B (passive, as Orekit reads it): in rotation.hpp's active Hamilton
// terms body <- inertial is R(conj Q) when Q transforms inertial to body, R(Q) the other way.
// Interpolation within a segment as INTERPOLATION_METHOD / INTERPOLATION_DEGREE say (absent:
// LINEAR, the geodesic): Lagrange of the samples' rotation vectors about the interval's first
// sample, exact for a rotation about a fixed axis by an angle polynomial of the degree; its error
// estimate is the angle to the interpolant with one sample more, at each interval's midpoint.
// The keywords, the conventions and how they were checked: docs/SOURCES.md, "CCSDS AEM".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "conescan/attitude.hpp"
#include "sources/rotation.hpp"
#include "sources/sampled_segment.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// Without INTERPOLATION_METHOD: the geodesic between the two samples around t.
inline constexpr interpolation_method aem_default_method = interpolation_method::linear;
/// Without INTERPOLATION_DEGREE (LAGRANGE or HERMITE named alone): a cubic.
inline constexpr int aem_default_degree = 3;

/// Data lines an AEM reader keeps at most (2^21, 104 MiB with the estimates); see oem_max_states.
inline constexpr std::size_t aem_max_samples = std::size_t{1} << 21;

struct aem_read_options {
  std::optional<time_span> span;  ///< keep only the samples interpolation over it needs
  std::size_t max_samples = aem_max_samples;
};

/// One segment: the rotation body <- inertial at each sample (rotation.hpp's q_BI, signs made
/// continuous), the frames and time system its META named.
struct aem_segment : sampled_segment<quaternion> {
  std::string inertial_frame;  ///< as written, e.g. "EME2000"
  std::string body_frame;      ///< e.g. "SC_BODY_1"
  time_scale time_system = time_scale::utc;
};

/// A rotation body <- inertial with the estimate of its interpolation error (angle_rad).
struct interpolated_attitude {
  quaternion body_from_inertial;  ///< q_BI: v_body = apply(dcm(), v_inertial)
  interval_error estimate;
  mat3<double> dcm() const noexcept { return rotation_matrix(body_from_inertial); }
};

/// The interpolated rotation at tau seconds from the segment's reference, in interval k.
interpolated_attitude interpolate_aem(const aem_segment& s, std::size_t k, double tau) noexcept;

/// An AEM once read: its segments, usable_start(), usable_stop(), worst_error(t0, t1), path()
/// (sampled_segment.hpp), and:
class aem_attitude : public sampled_file<aem_segment, interpolate_aem> {
 public:
  /// Before any row: nullopt when every time of [t0, t1] can be interpolated and, given
  /// max_angle_rad, no interval meeting the span has an error estimate above it.
  checked<void> check_coverage(const instant& t0, const instant& t1,
                               std::optional<double> max_angle_rad) const;

  /// The rotation body <- inertial at t from the segment that serves it; refused outside
  /// every usable span.
  checked<interpolated_attitude> attitude_at(const instant& t) const { return value_at(t); }

 private:
  friend checked<aem_attitude> read_aem(const std::string& path, const aem_read_options& options);
  using sampled_file::sampled_file;
};

checked<aem_attitude> read_aem(const std::string& path, const aem_read_options& options = {});

}  // namespace conescan::sources
