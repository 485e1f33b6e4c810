// --write-oem FILE and --write-aem FILE (MODEL §10): the scene's own orbit as a CCSDS
// Orbit Ephemeris Message that --oem reads back, and its true attitude as a CCSDS Attitude
// Ephemeris Message that --aem reads back (round trips: tests/apps/test_cli_sources.cpp).
//
// Both: KVN, one segment, TIME_SYSTEM UTC, one sample per row of the scene (t = k step), epochs to
// the nanosecond (format_utc), numbers in shortest round-trip decimal. The frame is TOD, the
// true equator and equinox of date (IAU 2006/2000A, ERFA), CCSDS's REF_FRAME "TOD": the scene
// frame every source was rotated into (MODEL §10), so that the file reads back to the same rows
// whatever frames the scene's sources were given in.
//  - OEM: CCSDS_OEM_VERS 2.0, CENTER_NAME EARTH, positions km, velocities km/s, INTERPOLATION
//    HERMITE, INTERPOLATION_DEGREE 7 (the reader's default); for a TLE's orbit LAGRANGE 7:
//    SGP4's velocity is not the exact derivative of its position (0.03 m/s apart on a LEO set),
//    which Hermite interpolation trusts: read back every 60 s, its estimate says 0.84 m
//    (0.00024 deg, refused), where Lagrange 7 reproduces SGP4's radius to 7e-5 m.
//  - AEM: CCSDS_AEM_VERS 1.0, REF_FRAME_A the inertial frame, REF_FRAME_B SC_BODY_1,
//    ATTITUDE_DIR A2B, QUATERNION_TYPE LAST (q1 q2 q3 qc, qc >= 0: CCSDS's coordinate
//    transformation inertial -> body, aem.hpp), INTERPOLATION_METHOD LAGRANGE, degree 7.
//
// All or nothing: written into a text::output_file (src/text/output_file.hpp: a temporary file
// beside FILE renamed over it by the caller's commit(), or a device written directly), which the
// program opens, with its other outputs, before it writes anything.
#pragma once

#include <string>

#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"
#include "text/output_file.hpp"

namespace conescan::scene {

/// Writes the orbit of `scene` (validated, its files loaded) at its rows' times to `out` (not
/// committed: the caller commits once every output is written). The error (option write-oem)
/// names the file and the system's reason, or the row where the orbit has no state.
checked<void> write_oem(const loaded_scene& scene, text::output_file& out);

/// The same for the true attitude (option write-aem).
checked<void> write_aem(const loaded_scene& scene, text::output_file& out);

}  // namespace conescan::scene
