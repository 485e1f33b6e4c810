// The scene frame (MODEL §10): the true equator and equinox of date (TOD), and the rotations of
// the other frames a source may use (TEME, EME2000, GCRF, ICRF, ITRF) into it, from ERFA (IAU 2006
// precession, IAU 2000A nutation): scene_rotations_at at one instant, frame_track over a scene's
// span for its rows. Accuracy: IAU 2006/2000A's; within 1.6e-11 rad of python3-erfa's other
// routes (tests/support/frames_oracle.py), 0.11 m (TEME) and 9 mm (PEF) from Vallado's published
// reduction of a TEME state to J2000 at 7000 km; velocities the inertial ones to |r| 1e-11 rad/s.
// The rotations, their conventions, what was decided and the sizes: docs/SUN_MOON.md, "Frames";
// their cost: its "Cost" table.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "conescan/attitude.hpp"
#include "sources/cartesian_state.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// The frames a source's states or attitudes may be given in (MODEL §10).
enum class reference_frame { tod, teme, eme2000, gcrf, icrf, itrf };

/// "TOD", "TEME", "EME2000", "GCRF", "ICRF", "ITRF".
std::string_view to_string(reference_frame frame) noexcept;

/// The frame of a CCSDS REF_FRAME value (CCSDS 500.0-G-4's names, exact case): TOD, TEME,
/// EME2000, GCRF, ICRF, and ITRF with any realisation (ITRF93, ITRF2000, ITRF2014, ITRF-97, ...;
/// the realisations differ by centimetres). nullopt for any other name.
std::optional<reference_frame> reference_frame_from_name(std::string_view name) noexcept;

/// The rotation of one frame into TOD (MODEL §10) at one instant: r_tod = M r,
/// v_tod = M (v + w z x r), w about the source frame's z axis (rad/s): 0 for the inertial frames,
/// the rate of the Earth rotation angle (earth_rotation_rate_rad_s) for ITRF.
struct rotation_to_tod {
  mat3<double> tod_from_source{1.0};
  double spin_rad_s = 0;
};

/// A state (m, m/s) in the source frame turned into TOD by `rotation` (formula above; MODEL §10).
/// Exact to rounding (1e-16 relative: round trips in tests/sources/test_scene_frame.cpp); the
/// velocity is the inertial one to ~|r| 1e-11 rad/s (top of file).
cartesian_state to_tod(const rotation_to_tod& rotation, const cartesian_state& source) noexcept;

/// Every rotation into TOD at one instant, from one evaluation of the nutation series.
struct scene_rotations {
  mat3<double> tod_from_gcrf{1.0};     ///< N P B
  mat3<double> tod_from_eme2000{1.0};  ///< N P
  mat3<double> tod_from_teme{1.0};     ///< R3(-EqE)
  double equation_of_equinoxes_rad = 0;
  double gast_rad = 0;  ///< Greenwich apparent sidereal time, [0, 2 pi)

  /// The rotation of `frame` (ITRF: R3(-GAST) and the Earth's rate).
  rotation_to_tod of(reference_frame frame) const noexcept;
};

/// The rotations into TOD (MODEL §10) at TT = tt, UT1 = ut1 (ERFA's two-part Julian dates; the
/// table of docs/SUN_MOON.md): eraNut06a once, eraPn06 for N P B and N P, eraEe00 with its
/// obliquity for EqE (= eraEe06a), eraGst06 with the same N P B for GAST (= eraGst06a). Any date
/// ERFA takes; the models are meant for a few centuries about 2000. Accuracy: IAU 2006/2000A's
/// (sub-mas); the matrices equal eraPnm06a's to 1e-15 rad and python3-erfa's other routes
/// to 1.6e-11 rad.
scene_rotations scene_rotations_at(const julian_date& tt, const julian_date& ut1) noexcept;

/// The same at an instant, UT1 = UTC + ut1_minus_utc_s (within the UTC table: time_scales.hpp).
scene_rotations scene_rotations_at(const instant& t, double ut1_minus_utc_s = 0.0) noexcept;

/// R3(-angle): the frame rotation about z that adds `angle` to right ascension (column-major;
/// R3(a) of a frame turned by a is about_z(-a)).
mat3<double> about_z(double angle_rad) noexcept;

/// The angle of a rotation matrix (rad, [0, pi]): atan2(|axis part|, trace part), accurate at
/// small angles (acos((trace - 1) / 2) would lose half the digits): a few ulp of the elements,
/// 1e-16 rad near 0 (the identity gives exactly 0).
double rotation_angle_rad(const mat3<double>& m) noexcept;

/// Nodes of frame_track: one per 6 h. Measured interpolation error over three days of 2026
/// (every 1234.5 s against direct calls, tests/sources/test_scene_frame.cpp): below 1e-11 rad
/// (2e-9 deg) for every frame.
inline constexpr double frame_track_node_spacing_s = 21600.0;

/// The rotations into TOD over a span, for rows: scene_rotations_at every
/// frame_track_node_spacing_s, four-point (cubic) Lagrange interpolation between: of the
/// matrices' elements for the inertial frames, of GAST - w t for ITRF (its slow part, the
/// equation of the origins) with w t added back, the UT1 seconds linear between nodes (exact for
/// the drift of UTC before 1972). ~20 ns a row (ITRF 37 ns) instead of ~25 us. Where UTC steps
/// within an interval (a leap second, or a step of the 1960s), UT1 = UTC + ut1_minus_utc_s steps
/// with it: rows in such an interval take UT1 from ERFA's table (~0.5 us a row, for at most one
/// interval per step). Accuracy: below 1e-11 rad (frame_track_node_spacing_s), leap seconds and
/// the 1960s included (tests/sources/test_scene_frame.cpp).
class frame_track {
 public:
  /// Nodes cover [t0, t1] (one more on either side). Refused (a diagnostic naming the span)
  /// outside the UTC table or for t1 < t0.
  static checked<frame_track> over(const instant& t0, const instant& t1,
                                   double ut1_minus_utc_s = 0.0);

  /// The rotation of `frame` into TOD at t. t outside [t0, t1] is extrapolated from the end
  /// nodes: the caller keeps to the span it asked for.
  rotation_to_tod at(reference_frame frame, const instant& t) const noexcept;

 private:
  struct node {
    mat3<double> tod_from_gcrf{1.0}, tod_from_eme2000{1.0}, tod_from_teme{1.0};
    double ut1_s = 0;          ///< UT1 seconds from the first node
    double gast_slow_rad = 0;  ///< GAST - w ut1_s, unwrapped
  };
  instant first_node_{};
  double ut1_minus_utc_s_ = 0;
  std::vector<node> nodes_;
};

}  // namespace conescan::sources
