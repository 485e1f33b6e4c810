// The Earth's rotation angle and the turn of an Earth-fixed (ITRF) state into the inertial frame
// conescan uses as ECI (MODEL §10): r_eci = R3(-ERA) r_itrf, v_eci = R3(-ERA) (v_itrf + w x
// r_itrf), w = earth_rotation_rate_rad_s along z.
//
// What this neglects, and what it costs:
//  - Polar motion (ITRF's pole against the CIP, < 0.5 arcsec): without --eop the states' z axis
//    stays the ITRF pole; a position moves by 17 m at most at 7000 km.
//  - UT1 - UTC: without IERS data (--eop) the caller passes 0; |UT1 - UTC| < 0.9 s by the
//    IERS's definition of UTC, so the angle about z is then off by up to 6.6e-5 rad (0.0038 deg:
//    0.46 km along the equator at 7000 km).
//  - Precession-nutation: the result is the Celestial Intermediate Reference System (CIRS: the
//    true equator of date, the CIO as x origin), not GCRF/EME2000, whose pole is 0.14 deg from
//    the CIP in 2025 (0.002 deg in 2000, 0.22 deg in 1960: precession-nutation, eraXy06). Horizon
//    geometry needs only |r| and the equator, so an ITRF ephemeris alone is fully consistent;
//    combined with an attitude relative to EME2000 (an AEM) the two frames differ by that rotation.
#pragma once

#include <numbers>

#include "sources/cartesian_state.hpp"
#include "sources/earth_orientation.hpp"
#include "sources/time_scales.hpp"

namespace conescan::sources {

/// d(ERA)/dt: 2 pi 1.00273781191135448 rad per UT1 day (IERS Conventions 2010, Eq. (5.15)),
/// 7.292115146706979e-5 rad/s (WGS84 rounds it to 7.292115e-5).
inline constexpr double earth_rotation_rate_rad_s =
    2.0 * std::numbers::pi * 1.00273781191135448 / 86400.0;

/// The Earth rotation angle (rad, [0, 2 pi)) at an instant, UT1 = UTC + ut1_minus_utc_s
/// (eraEra00: IERS Conventions 2010, Eq. (5.15)). Within ERFA's table (time_scales.hpp).
double earth_rotation_angle_rad(const instant& t, double ut1_minus_utc_s = 0.0) noexcept;

/// An ITRF state at instant t, turned inertial (top of file), the pole at the CIP.
cartesian_state inertial_from_itrf(const cartesian_state& itrf, const instant& t,
                                   double ut1_minus_utc_s = 0.0) noexcept;

/// The same with the Earth's orientation at t (--eop, earth_orientation.hpp): the pole's
/// coordinates first, r_tirs = W^T r_itrs with W = eraPom00(x_p, y_p, s') (s' = eraSp00, the
/// TIO locator: 47 microarcsec a century), the velocity turned alike (the pole's drift, a few
/// mas a day, neglected), then R3(-ERA(UT1)). Accuracy: ERFA's, and the values' (IERS: 10 us of
/// UT1, 0.1 mas of the pole for the final values; predictions drift by ms over weeks).
cartesian_state inertial_from_itrf(const cartesian_state& itrf, const instant& t,
                                   const earth_orientation_values& eop) noexcept;

}  // namespace conescan::sources
