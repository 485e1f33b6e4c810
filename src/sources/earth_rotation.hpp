// The Earth's rotation angle and the turn of an Earth-fixed (ITRF) state into the inertial frame
// conescan uses as ECI (MODEL §10): r_eci = R3(-ERA) r_itrf, v_eci = R3(-ERA) (v_itrf + w x
// r_itrf), w = earth_rotation_rate_rad_s along z.
//
// What this neglects, and what it costs:
//  - Polar motion (ITRF's pole against the CIP, < 0.5 arcsec): the states' z axis stays the ITRF
//    pole; a position moves by 17 m at most at 7000 km.
//  - UT1 - UTC: without IERS data the caller passes 0; |UT1 - UTC| < 0.9 s by the IERS's
//    definition of UTC, so the angle about z is then off by up to 6.6e-5 rad (0.0038 deg).
//  - Precession-nutation: the result is the Celestial Intermediate Reference System (CIRS: the
//    true equator of date, the CIO as x origin), not GCRF/EME2000, whose pole is 0.14 deg from
//    the CIP in 2025 (0.002 deg in 2000, 0.22 deg in 1960: precession-nutation, eraXy06). Horizon
//    geometry needs only |r| and the equator, so an ITRF ephemeris alone is fully consistent;
//    combined with an attitude relative to EME2000 (an AEM) the two frames differ by that rotation.
#pragma once

#include <numbers>

#include "sources/cartesian_state.hpp"
#include "sources/time_scales.hpp"

namespace conescan::sources {

/// d(ERA)/dt: 2 pi 1.00273781191135448 rad per UT1 day (IERS Conventions 2010, Eq. (5.15)),
/// 7.292115146706979e-5 rad/s (WGS84 rounds it to 7.292115e-5).
inline constexpr double earth_rotation_rate_rad_s =
    2.0 * std::numbers::pi * 1.00273781191135448 / 86400.0;

/// The Earth rotation angle (rad, [0, 2 pi)) at an instant, UT1 = UTC + ut1_minus_utc_s
/// (eraEra00: IERS Conventions 2010, Eq. (5.15)). Within ERFA's table (time_scales.hpp).
double earth_rotation_angle_rad(const instant& t, double ut1_minus_utc_s = 0.0) noexcept;

/// An ITRF state at instant t, turned inertial (top of file).
cartesian_state inertial_from_itrf(const cartesian_state& itrf, const instant& t,
                                   double ut1_minus_utc_s = 0.0) noexcept;

}  // namespace conescan::sources
