// The scene's truth (MODEL §10): where the satellite is, how it is turned and where the Sun is, at
// any time of the scene, in the scene frame (TOD, sources/scene_frame.hpp). One object, built from
// a validated scene whose files are loaded (scene_plan), answers
//
//   const auto truth = truth_source::of(scene);   // a loaded_scene; checked<truth_source>
//   truth_state s = truth.value().truth_at(t_s);   // t_s: seconds from the scene's epoch
//
// for the rows (simulation.cpp) and for anyone else who needs the same truth (the calibration's
// prediction of telemetry): the numbers the CSV rows were computed from. The orbit is one source
// (classical elements, --tle or --omm through SGP4, --oem), the attitude one (constant angles,
// --aem, --attitude-csv), the Sun's declination given or ERFA's at the row's time; a row's instant
// is epoch + t_s on TAI. Where a source has no value (SGP4 fails, a file does not cover t_s) the
// truth_state says so (ok false, every number NaN). Each source, its frame, the epoch's default
// and the cost: docs/SOURCES.md, "In the scene: truth_source" and "The scene frame".
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "conescan/vector.hpp"
#include "orbit/kepler.hpp"
#include "orbit/omm.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "sources/aem.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/earth_orientation.hpp"
#include "sources/oem.hpp"
#include "sources/scene_frame.hpp"
#include "sources/sun_declination.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

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

/// Reads and checks the files the scene names and its epoch (load_scene's work: loaded_scene.hpp
/// states the errors and what is kept of an OEM or AEM); on success at least the epoch.
checked<std::shared_ptr<const source_files>> load_source_files(const scene_config& scene,
                                                               bool span_may_change);

/// Before any row (validate() calls it): the scene's span [epoch, epoch + last row] lies within
/// ERFA's UTC table and each file's usable span (an OEM also with its interpolation error
/// estimate at most 1e-6 deg: sources::default_max_interpolation_angle_rad), and SGP4 gives a
/// state at the first and last rows and at least every tenth of an orbit between (a decay or an
/// eccentricity out of range is refused, naming the time). Errors as load_source_files'.
checked<void> check_source_coverage(const loaded_scene& scene);

/// With --interpolation-tolerance-deg above its default and an OEM whose interpolation error
/// estimate over [epoch, epoch + last_t_s] exceeds the default: what a program prints once on
/// standard error, the worst estimate and the bound it puts on each row's truth, (1 + tan rho)
/// times it (the Earth's angular radius rho at the epoch: SOURCES.md). nullopt otherwise.
std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene, double last_t_s);
/// The same over the scene's rows.
std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene);

/// The osculating two-body elements of a state (WGS84 GM): semi-major axis (m; <= 0 when not
/// bound), eccentricity and true anomaly (rad, (-pi, pi]; 0 on a circular orbit).
struct osculating_elements {
  double a_m;
  double e;
  double true_anomaly_rad;
};
osculating_elements osculating_of(const vec3<double>& r_m, const vec3<double>& v_m_s) noexcept;

/// The truth at one time. With `ok` false (SGP4 failed there, e.g. the satellite decayed, or a
/// file gave no value) every number is NaN: the row is written with status invalid.
struct truth_state {
  vec3<double> r_eci_m{0.0};    ///< position in the scene frame, TOD (MODEL §10; top of file)
  vec3<double> v_eci_m_s{0.0};  ///< velocity in the scene frame
  /// Classical elements: the Kepler orbit's, not wrapped (carries whole turns); file orbits: the
  /// osculating true anomaly of (r, v), (-pi, pi] (MODEL §10).
  double true_anomaly_rad = 0;
  /// True attitude: v_body = apply(body_from_orbit, v_orbital). The true roll and pitch the
  /// errors are taken against are those of the nadir (orbital +z) in body axes:
  /// roll_pitch_from_nadir(apply(body_from_orbit, {0, 0, 1})) (with constant angles: as given).
  mat3<double> body_from_orbit{1.0};
  double sun_declination_rad = 0;  ///< for the horizon's season term; 0 when the scene has none
  bool ok = true;
};

class truth_source {
 public:
  /// The truth of `scene`, which should be validated (scene_plan does it). The diagnostic: an
  /// epoch span the Sun's track or the frames' do not cover (a caller that skipped the plan's
  /// checks; bad input never gets here through scene_plan).
  static checked<truth_source> of(const loaded_scene& scene);

  /// The truth at t_s seconds from the epoch (any t_s the scene's rows use; outside them a file
  /// source may have no value: ok = false). Pure and thread-safe.
  truth_state truth_at(double t_s) const noexcept;

  /// What a caller asking for times in order carries from one truth_at to the next: a TLE's
  /// resonance integration (SDP4 on 12- and 24-hour orbits integrates from the epoch in 720-min
  /// steps; carried, a row far from the epoch costs what one near it does). One per thread.
  struct cursor {
    orbit::sgp4_propagator::resonance_cursor sgp4;
  };
  /// truth_at(t_s), bit for bit, carrying `carried` from the previous call.
  truth_state truth_at(double t_s, cursor& carried) const noexcept;

  /// The files read for the scene (and its epoch).
  const source_files& files() const noexcept { return *files_; }

  /// The scene's epoch (t_s = 0).
  const sources::instant& epoch() const noexcept { return epoch_; }

  /// Classical elements: the Kepler orbit (the pipeline's fast path runs it over blocks of rows).
  const orbit::kepler_orbit& kepler() const noexcept { return kepler_; }
  /// True when only the orbit changes from row to row and it is the Kepler orbit: constant
  /// attitude and constant Sun declination (the paper's scene).
  bool kepler_with_constant_attitude() const noexcept {
    return !(files_ && (files_->tle || files_->oem)) && !attitude_varies() && !sun_varies();
  }
  /// True when the attitude comes from a file (AEM, attitude CSV), or the Sun's declination
  /// from ERFA's track.
  bool attitude_varies() const noexcept { return files_ && (files_->aem || files_->attitude_csv); }
  bool sun_varies() const noexcept { return sun_track_.has_value(); }
  /// The constant attitude and declination of such a scene.
  const mat3<double>& constant_body_from_orbit() const noexcept { return body_from_orbit_; }
  double constant_sun_declination_rad() const noexcept { return sun_declination_rad_; }

 private:
  truth_source() = default;
  /// of()'s work once the files are loaded.
  checked<void> build(const loaded_scene& scene);
  void orbit_at(double t_s, const sources::instant& t, cursor& carried,
                truth_state& out) const noexcept;
  void attitude_at(double t_s, const sources::instant& t, truth_state& out) const noexcept;
  /// A state of `frame` at t in the scene frame (TOD).
  sources::cartesian_state in_scene_frame(const source_frame& frame, const sources::instant& t,
                                          const sources::cartesian_state& state) const noexcept;
  /// TOD <- the inertial frame of an attitude source at t.
  mat3<double> tod_from(sources::reference_frame frame, const sources::instant& t) const noexcept;

  sources::instant epoch_{};
  orbit::kepler_orbit kepler_;
  std::shared_ptr<const source_files> files_;
  mat3<double> body_from_orbit_{1.0};
  double sun_declination_rad_ = 0;
  std::optional<sources::sun_declination_track> sun_track_;
  /// The rotations into TOD over the scene's span (when a source needs one): ERA-rate cubic
  /// interpolation of ERFA every 6 h, 1e-11 rad (scene_frame.hpp).
  std::optional<sources::frame_track> frames_;
};

}  // namespace conescan::scene
