// The Sun and the Moon of a scene with --intrusions (MODEL §13): their track over the scene's
// span, built once, and per row the two bodies as the satellite sees them, in the scene frame.
// The simulation's intrusion step (simulation.cpp: sky_at, intrusion_check) turns them into body
// axes, decides whether the Earth hides each, and asks the core's rule (conescan/intrusion.hpp)
// for every head.
//
//   scene_sky sky = scene_sky::over(epoch, last_t_s).value();  // once per scene: ERFA every 6 h
//   scene_sky::bodies b = sky.at(t_s, r_tod_m);                // once per row: ~40 ns
//
// The scene frame is the true equator and equinox of date (TOD, MODEL §10). Classical elements
// are TOD elements, so a row's ECI position is its TOD position; the other orbit sources (a TLE's
// or an OMM's TEME, an OEM's frame) are rotated into TOD by the truth source (truth_source.hpp),
// so every row's position is a TOD position here.
//
// Options a scene with --intrusions cannot have (check_intrusions, validate()'s step; exit 2):
//  - --model bias: MODEL §13's rule is stated on the true scan cone (the optical axis A turned by
//    the misalignment, the cone gamma + dgamma) and its Earth pulse; the bias model has neither
//    (it folds the misalignment into a fixed cone angle about the spin axis, the paper's
//    approximation for the nadir angle), so the body's pulse and the Earth's would lie on two
//    different circles, up to sigma apart: a verdict at the limb would be a guess;
//  - --date and --sun-declination-deg: a fixed Sun for the horizon's season term beside the
//    rows' own Sun would be two Suns in one scene (no fallback to a fixed Sun, MODEL §13);
//  - a span whose track leaves the ephemerides' (TT 1950-01-01 to 2100-01-01T12:00,
//    sun_moon.hpp): the option that set it (the epoch, the file's epoch, or the duration).
#pragma once

#include "conescan/vector.hpp"
#include "scene/scene_config.hpp"
#include "sources/sun_moon.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// validate()'s check of --intrusions (top of file) on a scene whose rows span epoch to
/// epoch + last_t_s: success without it.
checked<void> check_intrusions(const scene_config& scene, const sources::instant& epoch,
                               double last_t_s);

class scene_sky {
 public:
  /// The Sun and Moon track from `epoch` to epoch + last_t_s (sun_moon_track::over). Errors:
  /// sun_moon_track's, without an option (check_intrusions names it before a scene gets here).
  static checked<scene_sky> over(const sources::instant& epoch, double last_t_s);

  /// The two bodies seen from the satellite (MODEL §13): unit direction from the satellite
  /// (TOD), distance and angular radius asin(R / distance).
  struct bodies {
    sources::body_view sun;
    sources::body_view moon;
  };

  /// The bodies at t_s seconds from the epoch (within the span: the track extrapolates beyond)
  /// seen from the satellite at r_tod_m (m, TOD; a non-finite position gives NaN directions).
  /// Accuracy: the track's (Moon 5.3e-6 deg, Sun 9e-10 deg, sun_moon.hpp) and one subtraction.
  bodies at(double t_s, const vec3<double>& r_tod_m) const noexcept;

 private:
  scene_sky(const sources::instant& epoch, sources::sun_moon_track track)
      : epoch_(epoch), track_(std::move(track)) {}
  sources::instant epoch_{};
  sources::sun_moon_track track_;
};

}  // namespace conescan::scene
