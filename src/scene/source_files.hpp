// The files a scene names (MODEL §10), once read and checked: the element set and its SGP4
// model, the OEM, the attitude files, the Earth orientation table, the scene's epoch and the file
// orbit's state there. load_scene (loaded_scene.hpp) reads them, once per plan; the truth
// (truth_source.hpp) and the checks of the scene's span use them. Each source, its frame and the
// epoch's default: docs/SOURCES.md, "In the scene: truth_source".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "conescan/vector.hpp"
#include "orbit/kepler.hpp"
#include "orbit/omm.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "scene/scene_config.hpp"
#include "sources/aem.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/earth_orientation.hpp"
#include "sources/oem.hpp"
#include "sources/scene_frame.hpp"
#include "sources/time_scales.hpp"

namespace conescan::scene {

/// Without --epoch and without a file that has its own: 2000-01-01T12:00:00 UTC (MODEL §10).
inline constexpr const char* default_epoch_utc = "2000-01-01T12:00:00";

/// The frame a source's states or attitudes are in, as they reach the scene: one of
/// scene_frame.hpp's frames, or the CIRS an ITRF OEM was turned into when it was read
/// (sources/oem.hpp), which goes to TOD by R3(-GAST) R3(ERA) (the equation of the origins).
struct source_frame {
  sources::reference_frame frame = sources::reference_frame::tod;
  bool cirs = false;
};

/// The files a scene names, read and checked once (at plan time), with what the rest of the
/// scene needs from them before any row. Immutable; shared by all scenes of a plan.
struct source_files {
  sources::instant epoch{};    ///< the scene's t = 0
  bool default_epoch = false;  ///< epoch is MODEL §10's default: no --epoch, TLE, OMM or OEM
  /// The element set SGP4 propagates, from --tle or --omm (an OMM's fields as a TLE holds them).
  std::optional<orbit::tle> tle;
  std::optional<orbit::omm_format> omm_format;  ///< set when the elements came from --omm
  std::optional<orbit::sgp4_propagator> sgp4;
  sources::instant tle_epoch{};  ///< the element set's epoch (UTC as it writes it)
  double tle_offset_s = 0;       ///< from the TLE's epoch to the scene's (TAI seconds)
  std::optional<sources::oem_ephemeris> oem;
  /// --eop's table, read before the OEM (whose ITRF states it turns).
  std::optional<sources::earth_orientation> eop;
  std::optional<sources::aem_attitude> aem;
  std::optional<sources::attitude_table> attitude_csv;
  /// The frame of each OEM segment and of each AEM segment's inertial side (in the files'
  /// order), and of a quaternion table (--attitude-frame).
  std::vector<source_frame> oem_frames;
  std::vector<sources::reference_frame> aem_frames;
  sources::reference_frame attitude_table_frame = sources::reference_frame::eme2000;
  /// The file orbit's state at t = 0 (ECI, SI): the osculating orbit that --orbits counts and
  /// the perigee check uses. Unset with classical elements.
  std::optional<orbit::orbit_state> state_at_epoch;

  /// SGP4's state at t_s seconds from the scene's epoch (sgp4 set): the one place the scene's
  /// seconds become the element set's minutes from its own epoch.
  orbit::teme_state sgp4_state_at(double t_s) const noexcept {
    return sgp4->state_at(sgp4_minutes(t_s));
  }
  /// The same, carrying a resonance integration from the previous time (sgp4.hpp).
  orbit::teme_state sgp4_state_at(
      double t_s, orbit::sgp4_propagator::resonance_cursor& carried) const noexcept {
    return sgp4->state_at(sgp4_minutes(t_s), carried);
  }

 private:
  double sgp4_minutes(double t_s) const noexcept { return (tle_offset_s + t_s) / 60.0; }
};

/// True when the scene's orbit, or attitude, comes from a file.
bool orbit_from_file(const scene_config& scene) noexcept;
/// The option that names the scene's orbit file ("tle", "omm", "oem"), or "" (elements).
const char* orbit_source_option(const scene_config& scene) noexcept;
/// The file that option names ("" with elements).
const std::string& orbit_source_file(const scene_config& scene) noexcept;
bool attitude_from_file(const scene_config& scene) noexcept;

/// SGP4's TEME state in SI (m, m/s).
inline sources::cartesian_state cartesian_of(const orbit::teme_state& s) {
  return {s.r_teme_km * 1000.0, s.v_teme_km_s * 1000.0};
}

/// The osculating two-body elements of a state (WGS84 GM): semi-major axis (m; <= 0 when not
/// bound), eccentricity and true anomaly (rad, (-pi, pi]; 0 on a circular orbit).
struct osculating_elements {
  double a_m;
  double e;
  double true_anomaly_rad;
};
osculating_elements osculating_of(const vec3<double>& r_m, const vec3<double>& v_m_s) noexcept;

}  // namespace conescan::scene
