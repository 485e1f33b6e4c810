#include "scene/scene_physics.hpp"

#include <cmath>
#include <string>
#include <tuple>

#include "conescan/scalar.hpp"
#include "conescan/sensor_physics/chain.hpp"
#include "conescan/sensor_physics/field.hpp"
#include "scene/head_spec.hpp"
#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

const head_config default_head{};
const scene_config default_scene{};

std::string outside(const char* name, double v, const char* range) {
  return std::string(name) + " = " + text::shortest_text(v) + " is outside " + range;
}

diagnostic refuse_head(std::size_t index, const std::string& what) {
  return diagnostic{"head", "head " + std::to_string(index + 1) + ": " + what, {}, index + 1};
}

// The radiance options: each finite and in its range. The scale height is 0 (the step edge) or
// at least 1 mm: below it no profile differs from the step at the chain's accuracy, and a
// subnormal H has no finite 1 / H (MODEL §12's profile is invalid there).
checked<void> check_radiance(const scene_config& s) {
  constexpr const char* scale_range = "0 or [1e-06, 1000] km";
  if (s.radiance_scale_km > 0 && s.radiance_scale_km < 1e-6)
    return diagnostic{
        "radiance-scale-km", outside("radiance-scale-km", s.radiance_scale_km, scale_range), {}};
  const struct {
    double value;
    const char* option;
    double lo, hi;
    bool open;  // (lo, hi) rather than [lo, hi]
    const char* range;
  } options[] = {
      {s.radiance_scale_km, "radiance-scale-km", 0, 1000, false, scale_range},
      {s.radiance_offset_km, "radiance-offset-km", -1000, 1000, false, "[-1000, 1000] km"},
      {s.radiance_disk, "radiance-disk", 0, 100, false, "[0, 100]"},
      {s.radiance_season, "radiance-season", -1, 1, true, "(-1, 1)"},
  };
  for (const auto& o : options) {
    const bool inside =
        o.open ? o.value > o.lo && o.value < o.hi : o.value >= o.lo && o.value <= o.hi;
    if (!inside) return diagnostic{o.option, outside(o.option, o.value, o.range), {}};
  }
  return success();
}

// The slope locator's lag (the core's lag_rad_of), at least the core's shortest: its
// y'' = (s' - y') / Lambda rounds as 1 / Lambda.
checked<void> check_slope_lag(const head_config& h, std::size_t index) {
  const double tau_s = h.tau_ms / 1000;
  const double shortest = shortest_slope_lag_rad<double>();
  if (!(tau_s > 0) || !(lag_rad_of(h.spin_hz, tau_s) < shortest)) return success();
  // The least tau-ms that passes, rounded up to two digits.
  const double least_ms = shortest / lag_rad_of(h.spin_hz, 1.0) * 1000;
  const double digit = std::pow(10.0, std::floor(std::log10(least_ms)) - 1);
  return refuse_head(index, "tau-ms = " + text::shortest_text(h.tau_ms) +
                                " at spin-hz = " + text::shortest_text(h.spin_hz) +
                                " is a lag shorter than locator=slope resolves (2 pi spin-hz tau "
                                "below " +
                                text::shortest_text(shortest) +
                                " rad of scan azimuth): give tau-ms=0 or at least " +
                                text::shortest_text(std::ceil(least_ms / digit) * digit));
}

// The threshold as its locator reads it, at least the core's lowest level (lowest_level: the
// chain's tolerances are fractions of L0).
checked<void> check_locator(const head_config& h, std::size_t index) {
  const double lowest = lowest_level<double>();
  const double lowest_k = lowest_normalised_threshold<double>();
  switch (h.locator) {
    case locator_kind::normalised:
      if (!(h.threshold >= lowest_k && h.threshold < 1))
        return refuse_head(index, outside("threshold", h.threshold,
                                          ("[" + text::shortest_text(lowest_k) +
                                           ", 1) (the normalised locator's fraction of the "
                                           "pulse's peak)")
                                              .c_str()));
      break;
    case locator_kind::fixed:
      if (!(h.threshold >= lowest && std::isfinite(h.threshold)))
        return refuse_head(index, outside("threshold", h.threshold,
                                          ("[" + text::shortest_text(lowest) +
                                           ", inf) (the fixed locator's level, in units of the "
                                           "limb's plateau L0 = 1)")
                                              .c_str()));
      break;
    case locator_kind::slope:
      if (h.threshold != default_head.threshold)
        return refuse_head(index, "threshold = " + text::shortest_text(h.threshold) +
                                      " is not used by locator=slope (the extremum of the "
                                      "output's slope): drop it");
      return check_slope_lag(h, index);
  }
  return success();
}

checked<void> check_head_physics(const head_config& h, std::size_t index) {
  for (const head_key& k : head_keys())
    if (k.group == head_key_group::physics && k.field && !std::isfinite(h.*k.field))
      return refuse_head(
          index, std::string(k.name) + " = " + text::shortest_text(h.*k.field) + " is not finite");
  // The core's narrowest field (a narrower one costs the chain cells as 1/fov).
  const double narrowest_deg = narrowest_field_deg<double>();
  if (!(h.fov_deg == 0 || (h.fov_deg >= narrowest_deg && h.fov_deg < 90)))
    return refuse_head(
        index, outside("fov", h.fov_deg,
                       ("0 or [" + text::shortest_text(narrowest_deg) + ", 90) deg").c_str()));
  // The field must not reach the spin axis (sensor_physics_crossings' invalid): its half-width
  // below the true cone's least angle from it.
  const double reach_deg = h.gamma_deg + h.dgamma_deg - h.sigma_deg;
  if (!(h.fov_deg / 2 < reach_deg))
    return refuse_head(index, "fov = " + text::shortest_text(h.fov_deg) +
                                  " reaches the spin axis: its half-width must be below gamma + "
                                  "dgamma - sigma = " +
                                  text::shortest_text(reach_deg) + " deg");
  // The lag in scan azimuth, 2 pi spin tau, then stays a normal double (>= 6e-12 rad).
  if (!(h.spin_hz == 0 || (h.spin_hz >= 0.001 && h.spin_hz <= 1000)))
    return refuse_head(index, outside("spin-hz", h.spin_hz, "0 or [0.001, 1000] rev/s"));
  if (!(h.tau_ms == 0 || (h.tau_ms >= 1e-6 && h.tau_ms <= 1000)))
    return refuse_head(index, outside("tau-ms", h.tau_ms, "0 or [1e-6, 1000] ms"));
  if (h.tau_ms > 0 && !(h.spin_hz > 0))
    return refuse_head(index, "tau-ms = " + text::shortest_text(h.tau_ms) +
                                  " needs spin-hz= (the scan rate turns the detector's time "
                                  "constant into scan azimuth)");
  return check_locator(h, index);
}

}  // namespace

const char* radiance_option_given(const scene_config& s) {
  const scene_config& d = default_scene;
  for (const auto& [value, fallback, option] :
       {std::tuple{s.radiance_scale_km, d.radiance_scale_km, "radiance-scale-km"},
        std::tuple{s.radiance_offset_km, d.radiance_offset_km, "radiance-offset-km"},
        std::tuple{s.radiance_disk, d.radiance_disk, "radiance-disk"},
        std::tuple{s.radiance_season, d.radiance_season, "radiance-season"}})
    if (value != fallback) return option;
  return nullptr;
}

bool radiance_given(const scene_config& s) {
  return radiance_option_given(s) != nullptr;
}

bool head_physics_given(const head_config& h) {
  for (const head_key& k : head_keys())
    if (k.group == head_key_group::physics && !k.same(h, default_head)) return true;
  return false;
}

bool physics_on(const scene_config& scene, const head_config& head) {
  return radiance_given(scene) || head_physics_given(head);
}

bool any_physics(const scene_config& scene) {
  for (const head_config& h : scene.heads)
    if (physics_on(scene, h)) return true;
  return false;
}

bool has_season_terms(const scene_config& scene) {
  return scene.horizon_shift_km != 0 || scene.radiance_season != 0;
}

sensor_physics_settings<double> physics_settings_of(const scene_config& scene,
                                                    const head_config& head) {
  sensor_physics_settings<double> s;
  s.field = {deg_to_rad(head.fov_deg), head.shape};
  s.spin_hz = head.spin_hz;
  s.tau_s = head.tau_ms / 1000;
  s.locator = {head.locator, head.threshold};
  s.scale_m = scene.radiance_scale_km * 1000;
  s.offset_m = scene.radiance_offset_km * 1000;
  s.disk = scene.radiance_disk;
  s.season_amplitude = scene.radiance_season;
  return s;
}

checked<void> check_physics(const scene_config& s) {
  for (const auto& [value, option] : {std::pair{s.radiance_scale_km, "radiance-scale-km"},
                                      std::pair{s.radiance_offset_km, "radiance-offset-km"},
                                      std::pair{s.radiance_disk, "radiance-disk"},
                                      std::pair{s.radiance_season, "radiance-season"}})
    if (!std::isfinite(value))
      return diagnostic{
          option,
          std::string(option) + " = " + text::shortest_text(value) + " is not a finite number",
          {}};
  if (checked<void> radiance = check_radiance(s); !radiance.ok()) return radiance;
  for (std::size_t k = 0; k < s.heads.size(); ++k)
    if (checked<void> head = check_head_physics(s.heads[k], k); !head.ok()) return head;
  if (s.model == forward_model::scan || !any_physics(s)) return success();
  // The bias model folds the misalignment into a fixed cone about the spin axis: no true scan
  // cone for the chain to trace. Blame what the user gave: a radiance option, else the head.
  const std::string why =
      " needs --model scan: MODEL §12's chain traces the true scan cone (the misaligned optical "
      "axis, gamma + dgamma), which the bias model does not";
  if (const char* option = radiance_option_given(s))
    return diagnostic{option, std::string(option) + why, {}};
  for (std::size_t k = 0; k < s.heads.size(); ++k)
    if (head_physics_given(s.heads[k]))
      return refuse_head(k, "the sensor physics (" + physics_keys_text() + ")" + why);
  return success();
}

}  // namespace conescan::scene
