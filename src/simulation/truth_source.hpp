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

#include "conescan/vector.hpp"
#include "orbit/kepler.hpp"
#include "orbit/sgp4.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/source_files.hpp"
#include "sources/scene_frame.hpp"
#include "sources/sun_declination.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

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
