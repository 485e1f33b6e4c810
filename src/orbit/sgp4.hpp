// SGP4/SDP4: the analytical propagator of NORAD's two-line element sets (MODEL §10).
//
// Written from the published algorithm: Hoots & Roehrich, "Models for Propagation of NORAD
// Element Sets", Spacetrack Report #3 (1980) [STR3], with the corrections of Vallado, Crawford,
// Hujsak & Kelso, "Revisiting Spacetrack Report #3", AIAA 2006-6753 [V06], whose reference code
// (sgp4unit, its "sgp4fix" changes included) defines the results. The stages keep the
// reference's names (sgp4init, initl, dscom, dpper, dsinit, dspace, sgp4) and its variable
// names, so that each line can be checked against [V06]'s listing; the long routines are split
// into named steps (sgp4.cpp). WGS-72 constants, as the model requires (the elements are fitted
// with them).
//
// Output: position (km) and velocity (km/s) in TEME ("true equator, mean equinox" of date, as
// astropy and Skyfield read it), at minutes since the element set's epoch. Deep space (SDP4)
// applies when the period is 225 min or more: lunar and solar perturbations, and the 12-hour and
// 24-hour geopotential resonances (numerically integrated from epoch in steps of 720 min).
//
// Accuracy: reproduces Vallado's verification output tcppver.out (33 satellites, 667 states)
// to within 2e-7 km and 2e-7 km/s with the same error codes, and python-sgp4 on random sets
// to 1e-6 km (tests/orbit/test_sgp4_*.cpp; worst differences in docs/SGP4.md). The model itself is
// an approximation, of order a kilometre at epoch and kilometres more each day against
// precise ephemerides (a commonly quoted figure, not measured here): that, not this code,
// bounds what its states mean.
#pragma once

#include <cstddef>

#include "conescan/vector.hpp"
#include "orbit/tle.hpp"

namespace conescan::orbit {

/// Why a state could not be computed: Vallado's error codes [V06] (5, "epoch elements are
/// sub-orbital", is no longer used there), and one of this library's own for input that is not
/// finite. With ok or decayed the state is finite; with any other status it is NaN.
enum class sgp4_status {
  ok = 0,
  mean_eccentricity = 1,       ///< mean eccentricity e >= 1 or e < -0.001 at the time
  mean_motion = 2,             ///< mean motion <= 0 at the time (drag)
  perturbed_eccentricity = 3,  ///< eccentricity after the lunar-solar periodics < 0 or > 1
  semi_latus_rectum = 4,       ///< semi-latus rectum < 0
  decayed = 6,                 ///< radius below 1 earth radius: the state is given, underground
  invalid_input = 100,         ///< an element or the time is not finite (not Vallado's)
};

/// A short description of a status, e.g. "the satellite has decayed (radius below the Earth's)".
const char* describe(sgp4_status status) noexcept;

/// [V06]'s operation mode. improved (Vallado's 'i', the default) computes Greenwich sidereal
/// time at epoch with the IAU-82 polynomial and leaves the node unwrapped in the Lyddane
/// modification; afspc ('a') keeps the Air Force Space Command code's 1970-based sidereal time
/// and its wrapping. tcppver.out was made in the improved mode.
enum class sgp4_mode { improved, afspc };

/// The mean elements as sgp4init takes them (radians, minutes, earth radii). The TLE's epoch
/// and B* fix the model; the derivatives of the mean motion of the TLE do not enter SGP4.
struct sgp4_elements {
  double epoch_days_since_1950;  ///< days from 1949 December 31, 0 h UTC (JD 2433281.5)
  double bstar;                  ///< 1/earth radii
  double eccentricity;           ///< ecco
  double argument_of_perigee_rad;
  double inclination_rad;
  double mean_anomaly_rad;
  double mean_motion_rad_min;  ///< Kozai mean motion, no_kozai
  double raan_rad;             ///< right ascension of the ascending node
};

/// A TLE's elements in the model's units, as the reference's twoline2rv computes them: degrees
/// to radians, rev/day to rad/min, and the epoch as one double Julian date minus 2433281.5
/// (a rounding to 4.7e-10 day that SDP4's states depend on: sgp4.cpp says why it is kept).
sgp4_elements mean_elements(const tle& set) noexcept;

/// A state in TEME (MODEL §10 uses TEME as the inertial frame).
struct teme_state {
  vec3<double> r_teme_km{0.0};
  vec3<double> v_teme_km_s{0.0};
  sgp4_status status = sgp4_status::ok;
};

/// Which geopotential resonance an SDP4 orbit has (dsinit's irez): none, the 24-hour
/// (geosynchronous, periods of 20-30 h) or the 12-hour one (periods of 11.3-12.7 h, e >= 0.5).
enum class sgp4_resonance { none = 0, synchronous = 1, half_day = 2 };

namespace sgp4_detail {

/// Near-earth coefficients of sgp4init ([STR3] §6, [V06]); Vallado's names.
struct near_earth_terms {
  double no_unkozai = 0;  ///< Brouwer mean motion, rad/min (initl's recovered no)
  double con41 = 0, x1mth2 = 0, x7thm1 = 0;
  double eta = 0, cc1 = 0, cc4 = 0, cc5 = 0, d2 = 0, d3 = 0, d4 = 0, delmo = 0, sinmao = 0;
  double mdot = 0, argpdot = 0, nodedot = 0;  ///< secular rates, rad/min
  double omgcof = 0, xmcof = 0, nodecf = 0, t2cof = 0, t3cof = 0, t4cof = 0, t5cof = 0;
  double xlcof = 0, aycof = 0;
  bool isimp = false;  ///< simplified drag (perigee below 220 km, and all of deep space)
};

/// The long-period periodic coefficients that one perturbing body (the Sun or the Moon) adds
/// (dscom's se2..sh3 for the Sun, ee2..xh3 for the Moon), with the body's mean anomaly at
/// epoch and its rate (dpper).
struct third_body_periodics {
  double e2 = 0, e3 = 0, i2 = 0, i3 = 0, l2 = 0, l3 = 0, l4 = 0, gh2 = 0, gh3 = 0, gh4 = 0;
  double h2 = 0, h3 = 0;
  double mean_anomaly_at_epoch = 0;  ///< zmos, zmol, rad
  double mean_motion = 0;            ///< zns, znl, rad/min
  double eccentricity = 0;           ///< zes, zel
};

/// The resonance integrator's last node: atime (min from epoch, a multiple of 720), the
/// resonance angle xli and the mean motion xni there.
struct resonance_node {
  double atime, xli, xni;
};

/// Deep-space coefficients of dsinit: lunar-solar secular rates and the resonance terms.
struct deep_space_terms {
  third_body_periodics sun, moon;
  double dedt = 0, didt = 0, dmdt = 0, dnodt = 0, domdt = 0;  ///< secular rates, per minute
  sgp4_resonance irez = sgp4_resonance::none;
  double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0, d4422 = 0, d5220 = 0;
  double d5232 = 0, d5421 = 0, d5433 = 0, del1 = 0, del2 = 0, del3 = 0;
  double xfact = 0, xlamo = 0;  ///< the resonance angle's rate offset and value at epoch
};

}  // namespace sgp4_detail

/// One satellite's SGP4/SDP4 model: sgp4init once, then any number of states. state_at keeps
/// no state between calls (the resonance integration restarts from epoch each time, which
/// gives the same numbers as the reference's resumed integration: the same steps from epoch),
/// so one propagator may serve several threads.
class sgp4_propagator {
 public:
  /// sgp4init: the model of these elements. Never fails: elements that are not finite, an
  /// eccentricity outside [0, 1) or a mean motion <= 0 (which a parsed TLE cannot hold) give
  /// invalid_input, mean_eccentricity or mean_motion at every time.
  explicit sgp4_propagator(const sgp4_elements& elements,
                           sgp4_mode mode = sgp4_mode::improved) noexcept;
  explicit sgp4_propagator(const tle& set, sgp4_mode mode = sgp4_mode::improved) noexcept;

  /// sgp4: the TEME state at `minutes_since_epoch` (either side of the epoch; resonant orbits
  /// take one integration step per 720 min from epoch).
  teme_state state_at(double minutes_since_epoch) const noexcept;

  /// Where a resonance integration stands between calls (the reference's atime, xli, xni). A
  /// new cursor starts from the epoch; a caller whose times move away from the epoch in order
  /// (a scene's rows) carries one from call to call, and the integration goes on from the last
  /// time instead of restarting (times that turn back restart from the epoch). A cursor
  /// belongs to one propagator and one thread.
  class resonance_cursor {
    friend class sgp4_propagator;
    sgp4_detail::resonance_node node_{0.0, 0.0, 0.0};
  };

  /// state_at(minutes_since_epoch), bit for bit, the resonance integration carried in `cursor`.
  teme_state state_at(double minutes_since_epoch, resonance_cursor& cursor) const noexcept;

  /// out[i] = state_at(t[i]) for i < count, bit for bit, faster for resonant orbits where the
  /// times move away from epoch in order (as a scene's rows do): the resonance integration
  /// goes on from the previous time instead of restarting from epoch, as the reference's
  /// dspace does between calls. A state of a 30-day run then costs about what one of a 1-day
  /// run does (docs/SGP4.md). Any order of times is allowed; times that turn back restart from
  /// epoch.
  void states_at(const double* minutes_since_epoch, teme_state* out,
                 std::size_t count) const noexcept;

  /// The status at epoch (what the reference's sgp4init returns).
  sgp4_status status_at_epoch() const noexcept { return status_at_epoch_; }

  /// True for SDP4: a period of 225 min or more.
  bool deep_space() const noexcept { return deep_space_; }

  /// The resonance an SDP4 orbit has (none for SGP4).
  sgp4_resonance resonance() const noexcept { return deep_.irez; }

 private:
  struct mean_state;  // the elements at one time, between the stages of state_at

  void initialize(const sgp4_elements& elements) noexcept;
  mean_state secular(double t) const noexcept;
  void deep_space_secular(double t, mean_state& m, resonance_cursor& cursor) const noexcept;
  void lunar_solar_periodics(double t, mean_state& m) const noexcept;
  teme_state position_velocity(const mean_state& m) const noexcept;

  sgp4_elements epoch_{};  // as given (the angles stay those of the TLE)
  sgp4_mode mode_;
  double gsto_ = 0;  // Greenwich sidereal time at epoch, rad
  bool deep_space_ = false;
  sgp4_detail::near_earth_terms near_{};
  sgp4_detail::deep_space_terms deep_{};
  sgp4_status input_status_ = sgp4_status::ok;  // elements the model refuses outright
  sgp4_status status_at_epoch_ = sgp4_status::ok;
};

}  // namespace conescan::orbit
