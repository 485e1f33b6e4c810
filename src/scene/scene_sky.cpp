#include "scene/scene_sky.hpp"

#include <string>

namespace conescan::scene {

namespace {

diagnostic refuse(const char* option, std::string message) {
  return diagnostic{option, std::move(message)};
}

// The option that set the scene's span, for an epoch or a duration the ephemerides do not cover.
const char* span_option(const scene_config& s) {
  if (!s.epoch_utc.empty()) return "epoch";
  if (!s.tle_file.empty()) return "tle";
  if (!s.oem_file.empty()) return "oem";
  return s.duration_s ? "duration-s" : "orbits";
}

}  // namespace

checked<void> check_intrusions(const scene_config& s, const sources::instant& epoch,
                               double last_t_s) {
  if (!s.intrusions) return success();
  if (s.model != forward_model::scan)
    return refuse("intrusions",
                  "needs --model scan: MODEL §13's rule is on the true scan cone "
                  "(the misaligned optical axis, gamma + dgamma), which the bias model does not "
                  "trace (it folds the misalignment into a fixed cone angle about the spin axis)");
  if (s.sun_declination_deg)
    return refuse("sun-declination-deg",
                  "--intrusions takes the Sun at each row's time from ERFA; a fixed declination "
                  "(--date, --sun-declination-deg) would be a second Sun in the scene: drop it "
                  "(the horizon's season term then follows the rows' Sun too)");
  const checked<void> span =
      sources::sun_moon_track::check_span(epoch, sources::add_seconds(epoch, last_t_s));
  if (!span.ok()) return refuse(span_option(s), "--intrusions: " + span.error().message);
  return success();
}

checked<scene_sky> scene_sky::over(const sources::instant& epoch, double last_t_s) {
  checked<sources::sun_moon_track> track =
      sources::sun_moon_track::over(epoch, sources::add_seconds(epoch, last_t_s));
  if (!track.ok()) return std::move(track).error();
  return scene_sky(epoch, std::move(track).value());
}

scene_sky::bodies scene_sky::at(double t_s, const vec3<double>& r_tod_m) const noexcept {
  const sources::sun_moon_positions p = track_.at(sources::add_seconds(epoch_, t_s));
  return {sources::view_from(p.sun_tod_m, sources::sun_radius_m, r_tod_m),
          sources::view_from(p.moon_tod_m, sources::moon_radius_m, r_tod_m)};
}

}  // namespace conescan::scene
