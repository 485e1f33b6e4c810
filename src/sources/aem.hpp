// CCSDS Attitude Ephemeris Message (AEM, CCSDS 504.0-B-1 and -B-2), KVN: read, and interpolated
// on the rotation group into the rotation body <- inertial at any time of its usable spans
// (MODEL §10).
//
// Read: the header (CCSDS_AEM_VERS 1 or 2 first; CREATION_DATE, ORIGINATOR), segments of a META
// block and a DATA_START/DATA_STOP block, COMMENT lines anywhere. Accepted: ATTITUDE_TYPE
// QUATERNION (the others refused by name), QUATERNION_TYPE FIRST or LAST, ATTITUDE_DIR A2B or
// B2A (mandatory in version 1; A2B when absent in version 2), one of REF_FRAME_A/B inertial
// (EME2000, GCRF, ICRF, TEME, TOD) and the other a spacecraft body frame (SC_BODY_n) — MODEL §10
// names an inertial A; the reverse pair is the same rotation read the other way and is accepted
// too; TIME_SYSTEM UTC, TAI, TT, GPS. CENTER_NAME is not needed for a rotation and is not checked.
// Quaternions must have unit norm within 1e-3 (they are normalised).
//
// Conventions (CCSDS 504.0-B-1 annex on quaternions; Orekit's AemAttitudeType reads them the
// same way): a CCSDS quaternion Q = (q1, q2, q3, qc), qc = cos(phi/2), (q1, q2, q3) = e sin(phi/2)
// "represents the coordinate transformation from frame A to frame B" for ATTITUDE_DIR A2B: frame
// B is frame A turned by phi about e (passive: it transforms coordinates), and
//   v_B = A(Q) v_A,  A(Q) = (qc^2 - |q|^2) I + 2 q q^T - 2 qc [q x]
// (Shuster's attitude matrix; Hipparchus' Rotation.applyTo, which Orekit's Attitude applies to a
// vector of the reference frame to get it in the spacecraft frame). With B2A the quaternion
// transforms B to A. QUATERNION_TYPE says where qc stands: FIRST (qc q1 q2 q3) or LAST.
// In rotation.hpp's active Hamilton terms A(Q) = R(conj Q), so the rotation body <- inertial is
// R(conj Q) when Q transforms inertial to body, R(Q) when it transforms body to inertial.
// Checked on hand-made files with known answers (tests/test_aem.cpp) and against Orekit's
// reading of AEMExample01.
//
// Interpolation, within a segment, as INTERPOLATION_METHOD / INTERPOLATION_DEGREE say (absent:
// LINEAR): the rotation vectors of the window's samples relative to the sample at the start of
// the interval that holds t, unwrapped across pi so that a spin stays continuous, interpolated
// by Lagrange of the degree (HERMITE too: quaternion samples carry no rates), and turned back
// into a rotation. LINEAR (degree 1) is then exactly the geodesic (slerp) between the two
// samples; degree d is exact for a rotation about a fixed axis by an angle polynomial of
// degree d. Quaternion signs do not matter (q and -q give the same rotation vector).
// Error estimate: the angle between this rotation and the one with the next sample added (one
// sample fewer when the segment has no more), at each interval's midpoint.
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
