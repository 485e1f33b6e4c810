#include "scene/sensor_preset.hpp"

#include "scene/head_spec.hpp"

namespace conescan::scene {

namespace {

// conical-15um's two heads (sensor_preset.hpp): the paper's OH-1 and OH-2, its 0.02 deg
// misalignment at full-budget.toml's phases (at 0 or 180 deg on both, the pair cancels it) and
// full-budget.toml's detector noise.
head_config preset_head(double beta_deg, double phase_deg) {
  head_config h;
  h.beta_deg = beta_deg;
  h.sigma_deg = 0.02;
  h.phase_deg = phase_deg;
  h.noise_deg = 0.01;
  return h;
}

// The preset's head keys, each unless the head's spec gave it.
void fill_in_head(head_config& h, const std::set<std::string>& keys) {
  const auto unless = [&](const char* key, auto apply) {
    if (!keys.count(key)) apply();
  };
  unless("fov", [&] { h.fov_deg = 1.5; });
  unless("spin-hz", [&] { h.spin_hz = 1; });
  unless("tau-ms", [&] { h.tau_ms = 1; });
}

}  // namespace

void fill_in_sensor_preset(scene_request& r, const std::function<bool(std::string_view)>& given,
                           const std::vector<std::set<std::string>>& head_keys) {
  if (r.sensor != sensor_preset::conical_15um) return;
  scene_config& s = r.scene;
  if (!given("earth")) s.earth = earth_model::wgs84;
  if (!given("model")) s.model = forward_model::scan;
  if (!given("horizon-preset")) r.preset = horizon_preset::co2_15um;
  if (!given("processing-radius")) s.processing_radius = processing_radius_kind::local;
  if (r.heads_given == 0) s.heads = {preset_head(90, 60), preset_head(-90, 200)};
  for (std::size_t k = 0; k < s.heads.size(); ++k)
    fill_in_head(s.heads[k], k < head_keys.size() ? head_keys[k] : std::set<std::string>());
}

}  // namespace conescan::scene
