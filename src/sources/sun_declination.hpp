// The Sun's apparent declination of date, for the apparent horizon's season term (MODEL §10:
// "the Sun's declination follows each row's time") and for --date (the declination at 12:00 UTC
// of the date).
//
// Method: conescan's one Sun, sun_moon.hpp's apparent Sun (eraEpv00, light time, annual
// aberration by eraAb) in the true equator of date (N P B, IAU 2006/2000A: scene_frame.hpp),
// whose pole is the CIP, the Earth's rotation axis, which is what the horizon's season term
// needs; the declination is atan2(z, hypot(x, y)).
//
// Accuracy: better than 1e-5 deg (the series and models are at the milliarcsecond level); TT
// from ERFA's table (TT = UTC + 32.184 s + TAI - UTC). Against the Astronomical Almanac's
// low-precision formula (which --date used before: tests/sources/test_sun_moon.cpp) within
// 0.0041 deg.
// Cost: ~50 us a call (the 1365-term nutation series): per-row calls would dominate a scene's
// time, so sun_declination_track samples it and interpolates.
#pragma once

#include <vector>

#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::sources {

/// The Sun's apparent declination of date (rad, north positive) at TT = tt (method above).
double apparent_sun_declination_rad(const julian_date& tt) noexcept;

/// The same at an instant (within ERFA's table).
double sun_declination_rad(const instant& t) noexcept;

/// The Sun's declination over a span: ERFA every sun_track_node_spacing_s, cubic (four-point
/// Lagrange) interpolation between. Interpolation error below 1e-9 deg (measured against direct
/// calls over a year, tests/sources/test_sun_declination.cpp); ~10 ns a call.
inline constexpr double sun_track_node_spacing_s = 21600.0;  // 6 h

class sun_declination_track {
 public:
  /// Nodes cover [t0, t1] (with one node more on either side); refused outside ERFA's table.
  static checked<sun_declination_track> over(const instant& t0, const instant& t1);

  /// The declination (rad) at t; t outside [t0, t1] is extrapolated from the end nodes (the
  /// caller keeps to the span it asked for).
  double at(const instant& t) const noexcept;

 private:
  instant first_node_{};
  std::vector<double> declination_rad_;
};

}  // namespace conescan::sources
