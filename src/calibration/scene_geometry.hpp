// The seam between the calibration and the scene's sources (SPEC §10, §11): the truth geometry of
// each telemetry row, i.e. everything the forward model needs that the fitted parameters do not
// change. ONE function, so that when the scene layer gains its own time-dependent sources (TLE,
// OEM, AEM: a scene-layer truth_at(t_s)), only scene_truth_at's body changes; the forward model
// (scene_model.hpp) and the program never see where the truth came from.
//
// Today: the scene's classical elements through the Kepler orbit (two-body, or with secular J2),
// the constant 3-2-1 reference attitude (--roll-deg, --pitch-deg, --yaw-deg) and the scene's
// constant Sun declination (--sun-declination-deg / --date), exactly as the simulation builds a
// row (src/scene/simulation.cpp).
#pragma once

#include <span>
#include <vector>

#include "calibration/input_error.hpp"
#include "conescan/attitude.hpp"
#include "scene/scene_config.hpp"

namespace conescan::calibration {

/// The truth of one row (SI): satellite state in ECI, reference attitude (orbital to body), and
/// the Sun's declination for the apparent horizon's season term.
struct row_truth {
  vec3<double> r_eci_m;
  vec3<double> v_eci_m_s;
  mat3<double> body_from_orbit;
  double sun_declination_rad = 0;
};

/// The truth at each time t_s (s from the scene's epoch) of a validated scene. Errors (option
/// "telemetry", naming the row's 1-based index among the times): a time outside the orbit
/// source's span. Classical elements have no span (every finite time is valid); the sources with
/// one (an ephemeris) will refuse here.
checked<std::vector<row_truth>> scene_truth_at(const scene::scene_config& scene,
                                               std::span<const double> times_s);

}  // namespace conescan::calibration
