#include "scene_calibration/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "simulation/simulation.hpp"
#include "simulation/truth_source.hpp"
#include "text/number_text.hpp"
#include "text/parallel_parts.hpp"

namespace conescan::calibration {

namespace {

// The scene with its span stretched to the telemetry's last time and its files read again for
// it (whole: the AEM the plan kept for the scene's own span may stop short).
checked<scene::loaded_scene> covering(const scene::loaded_scene& scene, double last_t_s) {
  if (!(last_t_s > scene::last_row_t_s(scene))) return scene;
  scene::scene_config s = scene.config;
  // Whole steps, so that the last row (a product k * step, MODEL §3) reaches the last time.
  s.duration_s = std::ceil(last_t_s / s.step_s) * s.step_s;
  checked<scene::loaded_scene> loaded = scene::load_scene(std::move(s), /*span_may_change=*/true);
  if (!loaded.ok()) return diagnostic{loaded.error().option, loaded.error().message};
  return loaded;
}

// A value's outcome without the value.
template <class T>
checked<void> checked_void(const checked<T>& c) {
  if (!c.ok()) return c.error();
  return success();
}

// Why the truth source has no value at t_s: the failing source's own words (they name its
// usable span).
std::string why_no_truth(const scene::truth_source& truth, double t_s) {
  const scene::source_files& f = truth.files();
  const sources::instant t = sources::add_seconds(truth.epoch(), t_s);
  if (f.sgp4) {
    const orbit::teme_state s = f.sgp4_state_at(t_s);
    if (s.status != orbit::sgp4_status::ok)
      return std::string(f.omm_format ? "--omm" : "--tle") + ": SGP4: " + orbit::describe(s.status);
  }
  if (f.oem) {
    const auto at = f.oem->state_at(t);
    if (!at.ok()) return "--oem: " + at.error().text();
  }
  if (f.aem) {
    const auto at = f.aem->attitude_at(t);
    if (!at.ok()) return "--aem: " + at.error().text();
  }
  if (f.attitude_csv) {
    const bool quaternions = f.attitude_csv->kind() == sources::attitude_table_kind::quaternions;
    const checked<void> at = quaternions ? checked_void(f.attitude_csv->body_from_inertial_at(t_s))
                                         : checked_void(f.attitude_csv->angles_at(t_s));
    if (!at.ok()) return "--attitude-csv: " + at.error().text();
  }
  return "the scene's sources give no state there";
}

}  // namespace

checked<void> scene_truth_each(const scene::loaded_scene& scene, std::span<const double> times_s,
                               int threads,
                               const std::function<void(std::size_t, const row_truth&)>& each) {
  if (times_s.empty()) return success();
  const auto row_error = [&](std::size_t i, const std::string& what) {
    return diagnostic{
        "telemetry", "t_s = " + text::shortest_text(times_s[i]) + ": " + what, {{}, i + 1}};
  };
  checked<scene::loaded_scene> s = covering(scene, times_s.back());
  if (!s.ok()) return s.error();
  checked<scene::truth_source> built = scene::truth_source::of(s.value());
  if (!built.ok())  // ERFA's tables do not reach the last time
    return row_error(times_s.size() - 1, built.error().text());
  const scene::truth_source& truth = built.value();
  const bool spanned = !truth.kepler_with_constant_attitude();
  std::vector<std::size_t> first_failure(text::parallel_part_count(times_s.size(), threads),
                                         times_s.size());
  const auto run_part = [&](std::size_t begin, std::size_t end, std::size_t part) {
    scene::truth_source::cursor carried;  // each part in time order, as the telemetry comes
    for (std::size_t i = begin; i < end; ++i) {
      const scene::truth_state t =
          spanned && times_s[i] < 0 ? scene::truth_state{} : truth.truth_at(times_s[i], carried);
      if ((spanned && times_s[i] < 0) || !t.ok) {
        first_failure[part] = i;
        return;
      }
      each(i, {t.r_eci_m, t.v_eci_m_s, t.body_from_orbit, t.sun_declination_rad});
    }
  };
  text::parallel_parts(times_s.size(), threads, run_part);
  const std::size_t failed = *std::min_element(first_failure.begin(), first_failure.end());
  if (failed == times_s.size()) return success();
  if (spanned && times_s[failed] < 0)
    return row_error(failed,
                     "before the scene's epoch (t_s = 0), where its sources start: give an "
                     "earlier --epoch and shift the telemetry's times");
  return row_error(failed, why_no_truth(truth, times_s[failed]));
}

checked<std::vector<row_truth>> scene_truth_at(const scene::loaded_scene& scene,
                                               std::span<const double> times_s) {
  std::vector<row_truth> out(times_s.size());
  checked<void> done =
      scene_truth_each(scene, times_s, 1, [&](std::size_t i, const row_truth& t) { out[i] = t; });
  if (!done.ok()) return done.error();
  return out;
}

checked<std::vector<status>> scene_head_statuses_at(const scene::loaded_scene& scene,
                                                    std::span<const double> times_s, int threads) {
  if (times_s.empty()) return std::vector<status>{};
  const auto row_error = [&](std::size_t i, const std::string& what) {
    return diagnostic{
        "telemetry", "t_s = " + text::shortest_text(times_s[i]) + ": " + what, {{}, i + 1}};
  };
  checked<scene::loaded_scene> s = covering(scene, times_s.back());
  if (!s.ok()) return s.error();
  checked<scene::simulation> built = scene::simulation::of(s.value(), threads);
  if (!built.ok())  // the stretched span leaves a source or the ephemerides
    return row_error(times_s.size() - 1, built.error().text());
  const scene::simulation& sim = built.value();
  std::vector<status> out;
  out.reserve(times_s.size() * sim.head_count());
  scene::row row = sim.make_row();
  for (std::size_t i = 0; i < times_s.size(); ++i) {
    if (scene.config.intrusions && times_s[i] < 0)
      return row_error(i,
                       "before the scene's epoch (t_s = 0), where --intrusions' Sun and Moon "
                       "start: give an earlier --epoch and shift the telemetry's times");
    sim.compute_at(times_s[i], row);
    for (const scene::head_row& h : row.heads) out.push_back(h.state);
  }
  return out;
}

}  // namespace conescan::calibration
