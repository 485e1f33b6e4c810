#include "scene/scene_config.hpp"

#include <cmath>

#include "conescan/scalar.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "scene/number_text.hpp"
#include "scene/scene_earth.hpp"

namespace conescan::scene {

namespace {

std::optional<config_error> require(bool ok, const char* option, const std::string& what) {
  if (ok) return std::nullopt;
  return config_error{option, what};
}

// "<name> = <v> is outside <range>"
std::string outside(const char* name, double v, const char* range) {
  return std::string(name) + " = " + shortest_text(v) + " is outside " + range;
}

double sun_sync_cos_i(const scene_config& s) {
  const orbit::earth_constants& w = orbit::wgs84();
  return orbit::sun_synchronous_cos_inclination(s.a_km * 1000, s.e, w.gm_m3_s2, w.j2, w.a_m);
}

std::optional<config_error> validate_head(const head_config& h, std::size_t index) {
  const std::string which = "head " + std::to_string(index + 1) + ": ";
  const struct {
    double value;
    const char* name;
  } values[] = {{h.alpha_deg, "alpha"}, {h.beta_deg, "beta"},   {h.gamma_deg, "gamma"},
                {h.sigma_deg, "sigma"}, {h.phase_deg, "phase"}, {h.noise_deg, "noise"},
                {h.lsb_deg, "lsb"}};
  const std::size_t head = index + 1;
  for (const auto& v : values)
    if (!std::isfinite(v.value))
      return config_error{"head",
                          which + v.name + " = " + shortest_text(v.value) + " is not finite", head};
  if (!(std::abs(h.alpha_deg) < 90))
    return config_error{"head", which + outside("alpha", h.alpha_deg, "(-90, 90) deg"), head};
  if (!(h.gamma_deg > 0 && h.gamma_deg < 90))
    return config_error{"head", which + outside("gamma", h.gamma_deg, "(0, 90) deg"), head};
  if (!(h.sigma_deg >= 0 && h.sigma_deg < h.gamma_deg))
    return config_error{"head", which + outside("sigma", h.sigma_deg, "[0, gamma) deg"), head};
  if (!(h.noise_deg >= 0 && h.noise_deg <= 10))
    return config_error{"head", which + outside("noise", h.noise_deg, "[0, 10] deg"), head};
  if (!(h.lsb_deg >= 0 && h.lsb_deg <= 10))
    return config_error{"head", which + outside("lsb", h.lsb_deg, "[0, 10] deg"), head};
  return std::nullopt;
}

}  // namespace

bool has_noise(const scene_config& scene) {
  for (const head_config& h : scene.heads)
    if (h.noise_deg > 0) return true;
  return false;
}

double orbital_period_s(const scene_config& scene) {
  return orbit::orbital_period_s(scene.a_km * 1000, orbit::wgs84().gm_m3_s2);
}

double effective_inclination_deg(const scene_config& scene) {
  if (!scene.sun_sync) return scene.i_deg;
  return rad_to_deg(std::acos(sun_sync_cos_i(scene)));
}

std::uint64_t row_count(const scene_config& scene) {
  const double duration =
      scene.duration_s ? *scene.duration_s : scene.orbits * orbital_period_s(scene);
  const double estimate = std::floor(duration / scene.step_s);
  if (!(estimate < 1.8e19)) return UINT64_MAX;
  auto k = static_cast<std::uint64_t>(estimate);
  // The quotient may be off by one ulp either way: settle on the product, as the grid does.
  while (static_cast<double>(k + 1) * scene.step_s <= duration) ++k;
  while (k > 0 && static_cast<double>(k) * scene.step_s > duration) --k;
  return k + 1;
}

std::optional<config_error> validate(const scene_config& s) {
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
                {s.roll_deg, "roll-deg"},
                {s.pitch_deg, "pitch-deg"},
                {s.yaw_deg, "yaw-deg"}};
  for (const auto& f : finite)
    if (!std::isfinite(f.value))
      return config_error{f.option, std::string(f.option) + " = " + shortest_text(f.value) +
                                        " is not a finite number"};
  // Physical ranges wide enough for any Earth-orbiting scene, narrow enough that no product of
  // them overflows or underflows (a^3 in m^3, GM / a^3; found by fuzzing, tests/test_robustness).
  if (auto err =
          require(s.a_km >= 1 && s.a_km <= 1e9, "a-km", outside("a-km", s.a_km, "[1, 1e9] km")))
    return err;
  if (auto err = require(s.e >= 0 && s.e < 1, "e", outside("e", s.e, "[0, 1)"))) return err;
  if (auto err = require(s.i_deg >= 0 && s.i_deg <= 180, "i-deg",
                         outside("i-deg", s.i_deg, "[0, 180] deg")))
    return err;
  if (auto err = require(s.step_s > 0, "step-s", outside("step-s", s.step_s, "(0, inf) s")))
    return err;
  if (s.duration_s) {
    if (auto err = require(std::isfinite(*s.duration_s) && *s.duration_s >= 0, "duration-s",
                           outside("duration-s", *s.duration_s, "[0, inf) s")))
      return err;
  } else if (auto err = require(s.orbits >= 0, "orbits", outside("orbits", s.orbits, "[0, inf)"))) {
    return err;
  }
  if (s.radius_km) {
    if (auto err = require(std::isfinite(*s.radius_km) && *s.radius_km >= 1 && *s.radius_km <= 1e6,
                           "radius-km", outside("radius-km", *s.radius_km, "[1, 1e6] km")))
      return err;
    if (auto err = require(s.earth == earth_model::sphere, "radius-km",
                           "radius-km applies to --earth sphere only (wgs84 uses WGS84 a and b)"))
      return err;
  }
  if (auto err = require(s.horizon_km >= 0 && s.horizon_km <= 1e4, "horizon-km",
                         outside("horizon-km", s.horizon_km, "[0, 1e4] km")))
    return err;
  if (auto err = require(s.model == forward_model::scan || s.earth == earth_model::sphere, "model",
                         "model bias needs --earth sphere: use --model scan with wgs84"))
    return err;
  // Perigee must clear the horizon surface; on wgs84 the equatorial radius is used whatever the
  // perigee's latitude (conservative: refuses a perigee between b + h and a + h over a pole).
  const double surface_km = truth_radius_m(s) / 1000 + s.horizon_km;
  const double perigee_km = s.a_km * (1 - s.e);
  if (auto err = require(perigee_km > surface_km, "e",
                         "perigee radius a-km (1 - e) = " + shortest_text(perigee_km) +
                             " km is not above the horizon surface (" + shortest_text(surface_km) +
                             " km): raise --a-km or lower --e"))
    return err;
  if (s.processing_horizon_km) {
    const double h = *s.processing_horizon_km;
    if (auto err = require(std::isfinite(h) && h >= 0 && h <= 1e4, "processing-horizon-km",
                           outside("processing-horizon-km", h, "[0, 1e4] km")))
      return err;
  }
  // The processing's sphere must lie below the orbit everywhere, or rho_p is undefined: its
  // radius is at most WGS84 a for equatorial and local, the truth's for the default.
  const double processing_radius_km = processing_sphere_of(s).radius_m / 1000;
  const double processing_surface_km =
      processing_radius_km + s.processing_horizon_km.value_or(s.horizon_km);
  if (s.processing_radius == processing_radius_kind::value) {
    const double p = s.processing_radius_km;
    if (auto err = require(std::isfinite(p) && p >= 1 && processing_surface_km < perigee_km,
                           "processing-radius",
                           outside("processing-radius", p,
                                   "[1, perigee radius - horizon-km) km, or equatorial|local")))
      return err;
  }
  if (auto err = require(processing_surface_km < perigee_km, "processing-radius",
                         "the processing's sphere (" + shortest_text(processing_surface_km) +
                             " km with its horizon) reaches the perigee radius (" +
                             shortest_text(perigee_km) +
                             " km): choose a smaller --processing-radius or a higher orbit"))
    return err;
  // The apparent horizon surface (issue 7).
  for (const auto& f : {std::pair{s.horizon_pole_km, "horizon-pole-km"},
                        std::pair{s.horizon_shift_km, "horizon-shift-km"}}) {
    if (auto err =
            require(std::isfinite(f.first), f.second,
                    std::string(f.second) + " = " + shortest_text(f.first) + " is not finite"))
      return err;
    if (auto err = require(f.first == 0 || s.earth == earth_model::wgs84, f.second,
                           std::string(f.second) + " shapes the WGS84 horizon: add --earth wgs84"))
      return err;
  }
  const double polar_km = horizon_polar_radius_m(s) / 1000;
  if (auto err = require(polar_km > 0, "horizon-pole-km",
                         "the horizon's polar radius b + horizon-km + horizon-pole-km = " +
                             shortest_text(polar_km) + " km must be > 0"))
    return err;
  if (s.sun_declination_deg) {
    if (auto err =
            require(std::isfinite(*s.sun_declination_deg) && std::abs(*s.sun_declination_deg) <= 90,
                    "sun-declination-deg",
                    outside("sun-declination-deg", *s.sun_declination_deg, "[-90, 90] deg")))
      return err;
  }
  if (auto err =
          require(s.horizon_shift_km == 0 || s.sun_declination_deg.has_value(), "horizon-shift-km",
                  "horizon-shift-km needs the Sun's declination: give --date YYYY-MM-DD or "
                  "--sun-declination-deg"))
    return err;

  if (auto err = require(s.runs >= 1, "runs", "runs = 0: give at least 1")) return err;
  if (auto err = require(std::abs(s.pitch_deg) < 90, "pitch-deg",
                         outside("pitch-deg", s.pitch_deg, "(-90, 90) deg")))
    return err;
  if (auto err = require(s.attitude_envelope_deg >= 0 && s.attitude_envelope_deg <= 90,
                         "attitude-envelope-deg",
                         outside("attitude-envelope-deg", s.attitude_envelope_deg, "[0, 90] deg")))
    return err;
  if (s.sun_sync) {
    const double c = sun_sync_cos_i(s);
    if (auto err = require(
            std::abs(c) <= 1, "sun-sync",
            "no sun-synchronous inclination exists for a-km = " + shortest_text(s.a_km) +
                ", e = " + shortest_text(s.e) + " (cos i would be " + shortest_text(c) + ")"))
      return err;
  }
  if (auto err = require(!s.heads.empty() && s.heads.size() <= max_heads, "head",
                         "a scene needs 1 to " + std::to_string(max_heads) + " heads, not " +
                             std::to_string(s.heads.size())))
    return err;
  for (std::size_t k = 0; k < s.heads.size(); ++k)
    if (auto err = validate_head(s.heads[k], k)) return err;
  const std::uint64_t per_run = row_count(s);
  const std::uint64_t rows =
      per_run > UINT64_MAX / s.runs ? UINT64_MAX : per_run * s.runs;  // all runs together
  if (auto err =
          require(rows <= s.max_rows, "max-rows",
                  "the scene has " +
                      (rows == UINT64_MAX ? std::string("over 1.8e19") : std::to_string(rows)) +
                      " rows, more than --max-rows = " + std::to_string(s.max_rows) +
                      ": raise --max-rows, or the step, or shorten the duration"))
    return err;
  return std::nullopt;
}

}  // namespace conescan::scene
