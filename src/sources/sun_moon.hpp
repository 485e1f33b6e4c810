// The Sun and the Moon for the scan (MODEL §13): geocentric positions from ERFA in the scene frame
// (TOD, scene_frame.hpp), in metres, then as a satellite sees them.
//
// Method:
//  Sun   eraEpv00 (VSOP2000-based series, 1900-2100: the Earth's heliocentric position to a few
//        km) at TT; the geocentric Sun is minus the heliocentric Earth, retarded by the light time
//        (499 s: the Sun's barycentric motion in it moves the Sun 7 km, 0.01 arcsec), then the
//        annual aberration by the Earth's barycentric velocity (eraAb, 20.5 arcsec: the largest
//        correction, kept because it is free), the distance kept geometric.
//  Moon  eraMoon98 (Meeus's truncated ELP2000-82: against ELP/MPP02 over 1950-2100, 2.9 arcsec
//        rms and 18.3 arcsec worst in direction, 6 km rms in distance) at TT, retarded by its light
//        time (1.3 s, 0.7 arcsec: the planetary aberration; the Earth's own velocity moves the
//        Moon's apparent place and the Earth's limb alike, as both ride with the Earth).
//  Both  rotated from the GCRS into TOD by N P B (scene_frame.hpp).
// Not applied: the satellite's own aberration (v/c < 2.7e-5 rad, 5.5 arcsec). It displaces the
// Earth's limb the same way, so the pulses' overlap, which is all the scan uses, does not move.
//
// Accuracy against the Astronomical Almanac's low-precision formulas over 2026 (independent,
// tests/sources/test_sun_moon.cpp): Sun within their stated 0.01 deg, Moon within their 0.3
// deg; the ERFA models themselves are better than 1e-5 deg (Sun) and 0.005 deg (Moon).
//
// Epochs: eraEpv00 is fitted 1900-2100, eraMoon98 compared 1950-2100; conescan takes both for
// TT in [1950-01-01T00:00, 2100-01-01T12:00) and refuses others (a caller exits 2; no fallback).
// Every instant of the UTC table (1960-2100, time_scales.hpp) lies inside.
//
// Cost (bench/sun_moon_speed.cpp): ~49 us a call with its rotation (eraEpv00 and the nutation
// series); rows take them from a sun_moon_track (cubic interpolation, ~13 ns a row).
#pragma once

#include <vector>

#include "conescan/attitude.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// Radii (m): the Sun's photosphere (696 000 km: 0.26657 deg at 1 au, MODEL §13's 0.2666 deg) and
/// the Moon's mean radius (1737.4 km, IAU WGCCRE).
inline constexpr double sun_radius_m = 696.0e6;
inline constexpr double moon_radius_m = 1.7374e6;

/// The span both ephemerides are taken over (TT Julian Dates): 1950-01-01T00:00 (the start of
/// eraMoon98's stated comparison) to 2100-01-01T12:00 (J2000 + 100 Julian years, where eraEpv00
/// starts to warn), which holds the UTC table's last second (2100-01-01T00:01:09 TT).
inline constexpr double sun_moon_first_jd_tt = 2433282.5;
inline constexpr double sun_moon_end_jd_tt = 2488070.0;

/// Geocentric apparent Sun and Moon (method above), TOD, m.
struct sun_moon_positions {
  vec3<double> sun_tod_m{0.0};
  vec3<double> moon_tod_m{0.0};
};

/// At TT = tt with the GCRS-to-TOD matrix of that time (scene_rotations::tod_from_gcrf). Refused
/// outside [sun_moon_first_jd_tt, sun_moon_end_jd_tt), or for a non-finite date, with a message
/// naming the span.
checked<sun_moon_positions> sun_moon_at(const julian_date& tt, const mat3<double>& tod_from_gcrf);

/// The same at an instant (its own rotation: scene_rotations_at).
checked<sun_moon_positions> sun_moon_at(const instant& t);

/// The Sun of sun_moon_at alone (geocentric, apparent: retarded and aberrated; TOD, m) at TT = tt
/// with the GCRS-to-TOD matrix of that time, without the span check: the one Sun of conescan,
/// whose declination the horizon's season term and --date take (sun_declination.hpp).
/// eraEpv00's domain (fitted 1900-2100; beyond, ERFA's series degrade slowly).
vec3<double> apparent_sun_tod_m(const julian_date& tt, const mat3<double>& tod_from_gcrf) noexcept;

/// A body as the satellite sees it, TOD.
struct body_view {
  vec3<double> direction_tod{0.0};  ///< unit, from the satellite to the body's centre
  double distance_m = 0;            ///< from the satellite
  double angular_radius_rad = 0;    ///< asin(radius / distance)
};

/// The body at body_tod_m (geocentric, m) of radius radius_m seen from the satellite at
/// satellite_tod_m: the difference of the two (the Moon's parallax reaches a degree from low
/// orbit, the Sun's 2e-3 deg from GEO). Domain: the satellite outside the body's sphere;
/// otherwise direction and radius are NaN.
body_view view_from(const vec3<double>& body_tod_m, double radius_m,
                    const vec3<double>& satellite_tod_m) noexcept;

/// Nodes of sun_moon_track: one per 6 h. Measured interpolation error over a lunar month of 2026
/// (random times against direct calls, tests/sources/test_sun_moon.cpp): Moon 5.3e-6 deg and
/// 142 m, Sun 9e-10 deg and 3 m; MODEL §13's budget for it is 1e-4 deg. (Hourly nodes: 4e-9 deg
/// and 0.1 m, for six times the nodes' cost.)
inline constexpr double sun_moon_track_node_spacing_s = 21600.0;

/// Sun and Moon over a span, for rows: sun_moon_at every sun_moon_track_node_spacing_s, four-point
/// (cubic) Lagrange interpolation of the TOD positions between.
class sun_moon_track {
 public:
  /// Nodes cover [t0, t1] (one more on either side). Refused outside the UTC table, outside the
  /// ephemerides' span, or for t1 < t0.
  static checked<sun_moon_track> over(const instant& t0, const instant& t1);

  /// What over(t0, t1) refuses, without evaluating a series: [t0, t1] outside the UTC table,
  /// t1 < t0, or a node of its track outside the ephemerides' span (the message names the span).
  /// A scene checks its span with it before any row (--intrusions: exit 2).
  static checked<void> check_span(const instant& t0, const instant& t1);

  /// The positions at t (t outside [t0, t1] is extrapolated from the end nodes).
  sun_moon_positions at(const instant& t) const noexcept;

 private:
  instant first_node_{};
  std::vector<sun_moon_positions> nodes_;
};

}  // namespace conescan::sources
