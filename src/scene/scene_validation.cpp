#include "scene/scene_validation.hpp"

#include <algorithm>
#include <cmath>

#include "conescan/scalar.hpp"
#include "orbit/wgs84.hpp"
#include "scene/head_spec.hpp"
#include "scene/scene_earth.hpp"
#include "scene/scene_physics.hpp"
#include "scene/scene_sky.hpp"
#include "scene/source_files.hpp"
#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

diagnostic refuse(const char* option, std::string what) {
  return diagnostic{option, std::move(what), {}};
}

// "<name> = <v> is outside <range>"
std::string outside(const char* name, double v, const char* range) {
  return std::string(name) + " = " + text::shortest_text(v) + " is outside " + range;
}

// From a TLE or an OEM: the osculating orbit's at the epoch (MODEL §10), a check of the scene's
// start; the rows' statuses show a satellite that later sinks into the horizon.
double perigee_km(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  if (scene.files && scene.files->state_at_epoch) {
    const orbit::orbit_state& st = *scene.files->state_at_epoch;
    const osculating_elements el = osculating_of(st.r_eci_m, st.v_eci_m_s);
    return el.a_m * (1 - el.e) / 1000;
  }
  return s.a_km * (1 - s.e);
}

// The Sun's declination the horizon's season term may take: the one given, else any of the
// year's (MODEL §10: the row's own; at most the obliquity, 23.44 deg, rounded up).
double largest_sun_declination_deg(const scene_config& s) {
  return s.sun_declination_deg ? std::abs(*s.sun_declination_deg) : 23.5;
}

checked<void> check_finite(const scene_config& s) {
  const struct {
    double value;
    const char* option;
  } finite[] = {{s.a_km, "a-km"},
                {s.e, "e"},
                {s.i_deg, "i-deg"},
                {s.raan_deg, "raan-deg"},
                {s.argp_deg, "argp-deg"},
                {s.m0_deg, "m0-deg"},
                {s.step_s, "step-s"},
                {s.orbits, "orbits"},
                {s.horizon_km, "horizon-km"},
                {s.horizon_pole_km, "horizon-pole-km"},
                {s.horizon_shift_km, "horizon-shift-km"},
                {s.roll_deg, "roll-deg"},
                {s.pitch_deg, "pitch-deg"},
                {s.yaw_deg, "yaw-deg"}};
  for (const auto& f : finite)
    if (!std::isfinite(f.value))
      return refuse(f.option, std::string(f.option) + " = " + text::shortest_text(f.value) +
                                  " is not a finite number");
  return success();
}

// Physical ranges wide enough for any Earth-orbiting scene, narrow enough that no product of
// them overflows or underflows (a^3 in m^3, GM / a^3; found by fuzzing, tests/test_robustness).
checked<void> check_orbit_and_time(const scene_config& s) {
  if (!(s.a_km >= 1 && s.a_km <= 1e9))
    return refuse("a-km", outside("a-km", s.a_km, "[1, 1e9] km"));
  if (!(s.e >= 0 && s.e < 1)) return refuse("e", outside("e", s.e, "[0, 1)"));
  if (!(s.i_deg >= 0 && s.i_deg <= 180))
    return refuse("i-deg", outside("i-deg", s.i_deg, "[0, 180] deg"));
  if (!(s.step_s > 0)) return refuse("step-s", outside("step-s", s.step_s, "(0, inf) s"));
  if (s.duration_s && !(std::isfinite(*s.duration_s) && *s.duration_s >= 0))
    return refuse("duration-s", outside("duration-s", *s.duration_s, "[0, inf) s"));
  if (!s.duration_s && !(s.orbits >= 0))
    return refuse("orbits", outside("orbits", s.orbits, "[0, inf)"));
  if (s.sun_sync) {
    const double c = sun_synchronous_cos_inclination(s);
    if (!(std::abs(c) <= 1))
      return refuse("sun-sync", "no sun-synchronous inclination exists for a-km = " +
                                    text::shortest_text(s.a_km) +
                                    ", e = " + text::shortest_text(s.e) + " (cos i would be " +
                                    text::shortest_text(c) + ")");
  }
  return success();
}

checked<void> check_truth_earth(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  if (s.radius_km) {
    if (!(std::isfinite(*s.radius_km) && *s.radius_km >= 1 && *s.radius_km <= 1e6))
      return refuse("radius-km", outside("radius-km", *s.radius_km, "[1, 1e6] km"));
    if (s.earth != earth_model::sphere)
      return refuse("radius-km",
                    "radius-km applies to --earth sphere only (wgs84 uses WGS84 a and b)");
  }
  if (!(s.horizon_km >= 0 && s.horizon_km <= 1e4))
    return refuse("horizon-km", outside("horizon-km", s.horizon_km, "[0, 1e4] km"));
  if (s.model != forward_model::scan && s.earth != earth_model::sphere)
    return refuse("model", "model bias needs --earth sphere: use --model scan with wgs84");
  // Perigee must clear the horizon surface; on wgs84 the equatorial radius is used whatever the
  // perigee's latitude (conservative: refuses a perigee between b + h and a + h over a pole).
  const double surface_km = truth_radius_m(s) / 1000 + s.horizon_km;
  if (orbit_from_file(s) && !(perigee_km(scene) > surface_km))
    return refuse(orbit_source_option(s), "the osculating perigee radius at the epoch, " +
                                              text::shortest_text(perigee_km(scene)) +
                                              " km, is not above the horizon surface (" +
                                              text::shortest_text(surface_km) + " km)");
  if (!(perigee_km(scene) > surface_km))
    return refuse("e", "perigee radius a-km (1 - e) = " + text::shortest_text(perigee_km(scene)) +
                           " km is not above the horizon surface (" +
                           text::shortest_text(surface_km) + " km): raise --a-km or lower --e");
  return success();
}

// The apparent horizon surface: its polar radius and the seasonal shift of its centre.
checked<void> check_apparent_horizon(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  for (const auto& f : {std::pair{s.horizon_pole_km, "horizon-pole-km"},
                        std::pair{s.horizon_shift_km, "horizon-shift-km"}})
    if (f.first != 0 && s.earth != earth_model::wgs84)
      return refuse(f.second,
                    std::string(f.second) + " shapes the WGS84 horizon: add --earth wgs84");
  const double polar_km = horizon_polar_radius_m(s) / 1000;
  if (!(polar_km > 0))
    return refuse("horizon-pole-km",
                  "the horizon's polar radius b + horizon-km + horizon-pole-km = " +
                      text::shortest_text(polar_km) + " km must be > 0");
  if (s.sun_declination_deg &&
      !(std::isfinite(*s.sun_declination_deg) && std::abs(*s.sun_declination_deg) <= 90))
    return refuse("sun-declination-deg",
                  outside("sun-declination-deg", *s.sun_declination_deg, "[-90, 90] deg"));
  if (s.earth != earth_model::wgs84) return success();
  // The satellite must stay outside the apparent surface: its farthest point from the Earth's
  // centre, max(a + h0, polar radius) + |shift sin(declination)|, below the perigee
  // (conservative, as the perigee check above: the perigee need not lie over a pole).
  const double shift_km =
      std::abs(s.horizon_shift_km * std::sin(deg_to_rad(largest_sun_declination_deg(s))));
  const double equatorial_km = truth_radius_m(s) / 1000 + s.horizon_km;
  const double reach_km = std::max(equatorial_km, polar_km) + shift_km;
  if (!(perigee_km(scene) > reach_km))
    return refuse(polar_km > equatorial_km ? "horizon-pole-km" : "horizon-shift-km",
                  "the apparent horizon reaches " + text::shortest_text(reach_km) +
                      " km from the Earth's centre (polar radius " + text::shortest_text(polar_km) +
                      " km, centre shifted by " + text::shortest_text(shift_km) +
                      " km), not below the perigee radius " +
                      text::shortest_text(perigee_km(scene)) +
                      " km: the satellite would fly inside the horizon");
  return success();
}

// The processing's sphere must lie below the orbit everywhere, or rho_p is undefined: its
// radius is at most WGS84 a for equatorial and local, the truth's for the default.
checked<void> check_processing(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  if (s.processing_horizon_km) {
    const double h = *s.processing_horizon_km;
    if (!(std::isfinite(h) && h >= 0 && h <= 1e4))
      return refuse("processing-horizon-km", outside("processing-horizon-km", h, "[0, 1e4] km"));
  }
  const double processing_surface_km =
      processing_sphere_of(s).radius_m / 1000 + s.processing_horizon_km.value_or(s.horizon_km);
  if (s.processing_radius == processing_radius_kind::value) {
    const double p = s.processing_radius_km;
    if (!(std::isfinite(p) && p >= 1 && processing_surface_km < perigee_km(scene)))
      return refuse("processing-radius",
                    outside("processing-radius", p,
                            "[1, perigee radius - horizon-km) km, or equatorial|local"));
  }
  if (!(processing_surface_km < perigee_km(scene)))
    return refuse("processing-radius",
                  "the processing's sphere (" + text::shortest_text(processing_surface_km) +
                      " km with its horizon) reaches the perigee radius (" +
                      text::shortest_text(perigee_km(scene)) +
                      " km): choose a smaller --processing-radius or a higher orbit");
  return success();
}

checked<void> check_head(const head_config& h, std::size_t index) {
  const std::string which = "head " + std::to_string(index + 1) + ": ";
  const auto refuse_head = [&](const std::string& what) {
    return diagnostic{"head", which + what, {}, index + 1};
  };
  // The physics keys are check_physics's (scene_physics.hpp).
  for (const head_key& k : head_keys())
    if (k.group != head_key_group::physics && k.field && !std::isfinite(h.*k.field))
      return refuse_head(std::string(k.name) + " = " + text::shortest_text(h.*k.field) +
                         " is not finite");
  if (!(std::abs(h.alpha_deg) < 90))
    return refuse_head(outside("alpha", h.alpha_deg, "(-90, 90) deg"));
  if (!(h.gamma_deg > 0 && h.gamma_deg < 90))
    return refuse_head(outside("gamma", h.gamma_deg, "(0, 90) deg"));
  if (!(h.sigma_deg >= 0 && h.sigma_deg < h.gamma_deg))
    return refuse_head(outside("sigma", h.sigma_deg, "[0, gamma) deg"));
  if (!(h.noise_deg >= 0 && h.noise_deg <= 10))
    return refuse_head(outside("noise", h.noise_deg, "[0, 10] deg"));
  // A step below 1e-9 deg quantises nothing a double can tell apart, and one of 1e-320 would
  // overflow chord / lsb: 0 or [1e-9, 10].
  if (!(h.lsb_deg == 0 || (h.lsb_deg >= 1e-9 && h.lsb_deg <= 10)))
    return refuse_head(outside("lsb", h.lsb_deg, "0 or [1e-9, 10] deg"));
  // The true cone gamma + dgamma obeys gamma's own domain (and stays above sigma).
  const double true_gamma_deg = h.gamma_deg + h.dgamma_deg;
  if (!(true_gamma_deg > 0 && true_gamma_deg < 90 && h.sigma_deg < true_gamma_deg))
    return refuse_head(outside("dgamma", h.dgamma_deg, "gamma + dgamma in (sigma, 90) deg"));
  for (const auto& [value, name] :
       {std::pair{h.bias_in_deg, "bias-in"}, std::pair{h.bias_out_deg, "bias-out"}})
    if (!(std::abs(value) <= 10)) return refuse_head(outside(name, value, "[-10, 10] deg"));
  return success();
}

static_assert(max_interpolation_tolerance_deg == 1, "the message below says (0, 1]");

checked<void> check_heads_and_attitude(const scene_config& s) {
  // +-90 deg included: a well-defined attitude (the nadir along -+x) whose roll is undefined,
  // which every row reports as status gimbal (MODEL §7), as it does for an attitude file there.
  if (!(std::abs(s.pitch_deg) <= 90))
    return refuse("pitch-deg", outside("pitch-deg", s.pitch_deg, "[-90, 90] deg"));
  if (!(s.interpolation_tolerance_deg > 0 &&
        s.interpolation_tolerance_deg <= max_interpolation_tolerance_deg))
    return refuse(
        "interpolation-tolerance-deg",
        outside("interpolation-tolerance-deg", s.interpolation_tolerance_deg, "(0, 1] deg"));
  if (!(s.attitude_envelope_deg >= 0 && s.attitude_envelope_deg <= 90))
    return refuse("attitude-envelope-deg",
                  outside("attitude-envelope-deg", s.attitude_envelope_deg, "[0, 90] deg"));
  if (s.heads.empty() || s.heads.size() > max_heads)
    return refuse("head", "a scene needs 1 to " + std::to_string(max_heads) + " heads, not " +
                              std::to_string(s.heads.size()));
  for (std::size_t k = 0; k < s.heads.size(); ++k)
    if (checked<void> head = check_head(s.heads[k], k); !head.ok()) return head;
  return success();
}

checked<void> check_rows(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  if (s.runs < 1) return refuse("runs", "runs = 0: give at least 1");
  const std::uint64_t per_run = row_count(scene);
  const std::uint64_t rows =
      per_run > UINT64_MAX / s.runs ? UINT64_MAX : per_run * s.runs;  // all runs together
  if (rows > s.max_rows)
    return refuse("max-rows",
                  "the scene has " +
                      (rows == UINT64_MAX ? std::string("over 1.8e19") : std::to_string(rows)) +
                      " rows, more than --max-rows = " + std::to_string(s.max_rows) +
                      ": raise --max-rows, or the step, or shorten the duration");
  return success();
}

// MODEL §10: the files a scene names, and its epoch, are read before it is validated
// (load_scene); the checks below take them from scene.files.
checked<void> check_files_loaded(const loaded_scene& scene) {
  const scene_config& s = scene.config;
  if (!scene.files)
    return refuse(orbit_from_file(s)             ? orbit_source_option(s)
                  : !s.aem_file.empty()          ? "aem"
                  : !s.attitude_csv_file.empty() ? "attitude-csv"
                                                 : "epoch",
                  "the scene's files were not read (load_scene)");
  return success();
}

}  // namespace

checked<void> validate(const loaded_scene& scene) {
  using step = checked<void> (*)(const loaded_scene&);
  const step steps[] = {check_files_loaded,
                        [](const loaded_scene& l) { return check_finite(l.config); },
                        [](const loaded_scene& l) { return check_orbit_and_time(l.config); },
                        check_truth_earth,
                        check_apparent_horizon,
                        check_processing,
                        [](const loaded_scene& l) { return check_heads_and_attitude(l.config); },
                        [](const loaded_scene& l) { return check_physics(l.config); },
                        check_rows,
                        check_source_coverage,
                        [](const loaded_scene& l) {
                          return check_intrusions(l.config, l.files->epoch, last_row_t_s(l));
                        }};
  for (const step check : steps)
    if (checked<void> outcome = check(scene); !outcome.ok()) return outcome;
  return success();
}

}  // namespace conescan::scene
