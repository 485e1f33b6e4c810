#include "scene/budget.hpp"

#include "scene/scene_earth.hpp"

namespace conescan::scene {

namespace {

std::vector<budget_source> source_scenes(const scene_config& all) {
  // The common ground of the single-source runs: the scan model on the sphere the processing
  // assumes, with every error source off.
  scene_config quiet = all;
  quiet.model = forward_model::scan;
  quiet.earth = earth_model::sphere;
  quiet.horizon_pole_km = quiet.horizon_shift_km = 0;
  quiet.geodetic_flattening = true;
  quiet.processing_horizon_km.reset();
  quiet.radius_km = processing_sphere_of(all).radius_m / 1000;
  quiet.processing_radius = processing_radius_kind::truth;
  for (head_config& h : quiet.heads)
    h.sigma_deg = h.noise_deg = h.lsb_deg = h.dgamma_deg = h.bias_in_deg = h.bias_out_deg = 0;
  // The sensor physics off (MODEL §12): every head a pencil beam without lag, the crossings
  // MODEL §5's.
  const scene_config defaults;
  const head_config default_head;
  quiet.radiance_scale_km = defaults.radiance_scale_km;
  quiet.radiance_offset_km = defaults.radiance_offset_km;
  quiet.radiance_disk = defaults.radiance_disk;
  quiet.radiance_season = defaults.radiance_season;
  for (head_config& h : quiet.heads) {
    h.fov_deg = default_head.fov_deg;
    h.shape = default_head.shape;
    h.spin_hz = default_head.spin_hz;
    h.tau_ms = default_head.tau_ms;
    h.locator = default_head.locator;
    h.threshold = default_head.threshold;
  }

  bool misaligned = false, noisy = false, stepped = false, biased = false;
  bool field = false, lagged = false, located = false;
  for (const head_config& h : all.heads) {
    misaligned = misaligned || h.sigma_deg > 0;
    biased = biased || h.dgamma_deg != 0 || h.bias_in_deg != 0 || h.bias_out_deg != 0;
    noisy = noisy || h.noise_deg > 0;
    stepped = stepped || h.lsb_deg > 0;
    field = field || h.fov_deg > 0;
    lagged = lagged || h.tau_ms > 0;
    located = located || h.locator != default_head.locator || h.threshold != default_head.threshold;
  }
  const bool radiant = located || all.radiance_offset_km != defaults.radiance_offset_km ||
                       all.radiance_disk != defaults.radiance_disk ||
                       all.radiance_season != defaults.radiance_season;
  std::vector<budget_source> sources;
  auto add = [&](const char* name, auto&& switch_on) {
    scene_config s = quiet;
    switch_on(s);
    sources.push_back({name, s});
  };
  if (misaligned)
    add("misalignment", [&](scene_config& s) {
      for (std::size_t k = 0; k < s.heads.size(); ++k)
        s.heads[k].sigma_deg = all.heads[k].sigma_deg;
    });
  // the fixed head biases: the cone-angle bias and the crossing biases together.
  if (biased)
    add("head-biases", [&](scene_config& s) {
      for (std::size_t k = 0; k < s.heads.size(); ++k) {
        s.heads[k].dgamma_deg = all.heads[k].dgamma_deg;
        s.heads[k].bias_in_deg = all.heads[k].bias_in_deg;
        s.heads[k].bias_out_deg = all.heads[k].bias_out_deg;
      }
    });
  if (all.earth == earth_model::wgs84)
    add("oblateness", [&](scene_config& s) {
      s.earth = earth_model::wgs84;
      s.radius_km.reset();
      s.processing_radius = all.processing_radius;
      s.processing_radius_km = all.processing_radius_km;
    });
  if (all.processing_horizon_km && *all.processing_horizon_km != all.horizon_km)
    add("horizon-height",
        [&](scene_config& s) { s.processing_horizon_km = all.processing_horizon_km; });
  // The latitude and season terms on a sphere of radius a + h0: the apparent surface machinery
  // with the geodetic flattening switched off, processed on that sphere.
  auto apparent_sphere = [&](scene_config& s) {
    s.earth = earth_model::wgs84;
    s.radius_km.reset();
    s.geodetic_flattening = false;
    s.processing_radius = processing_radius_kind::equatorial;
  };
  if (all.horizon_pole_km != 0)
    add("horizon-pole", [&](scene_config& s) {
      apparent_sphere(s);
      s.horizon_pole_km = all.horizon_pole_km;
    });
  if (all.horizon_shift_km != 0)
    add("horizon-season", [&](scene_config& s) {
      apparent_sphere(s);
      s.horizon_shift_km = all.horizon_shift_km;
    });
  // The sensor physics (MODEL §12), each on the profile's scale height as given: the field
  // (its shape too), the detector's lag, and what the radiance and the locator make of the
  // horizon (the 50 % point's offset, the disk, the season term, the locator and its threshold:
  // the height the pulse is cut at, and how it varies).
  if (field)
    add("field-of-view", [&](scene_config& s) {
      s.radiance_scale_km = all.radiance_scale_km;
      for (std::size_t k = 0; k < s.heads.size(); ++k) {
        s.heads[k].fov_deg = all.heads[k].fov_deg;
        s.heads[k].shape = all.heads[k].shape;
      }
    });
  if (lagged)
    add("detector-lag", [&](scene_config& s) {
      s.radiance_scale_km = all.radiance_scale_km;
      for (std::size_t k = 0; k < s.heads.size(); ++k) {
        s.heads[k].spin_hz = all.heads[k].spin_hz;
        s.heads[k].tau_ms = all.heads[k].tau_ms;
      }
    });
  if (radiant)
    add("radiance", [&](scene_config& s) {
      s.radiance_scale_km = all.radiance_scale_km;
      s.radiance_offset_km = all.radiance_offset_km;
      s.radiance_disk = all.radiance_disk;
      s.radiance_season = all.radiance_season;
      for (std::size_t k = 0; k < s.heads.size(); ++k) {
        s.heads[k].locator = all.heads[k].locator;
        s.heads[k].threshold = all.heads[k].threshold;
      }
    });
  if (noisy)
    add("noise", [&](scene_config& s) {
      for (std::size_t k = 0; k < s.heads.size(); ++k)
        s.heads[k].noise_deg = all.heads[k].noise_deg;
    });
  if (stepped)
    add("quantisation", [&](scene_config& s) {
      for (std::size_t k = 0; k < s.heads.size(); ++k) s.heads[k].lsb_deg = all.heads[k].lsb_deg;
    });
  scene_config everything = all;
  everything.model = forward_model::scan;
  sources.push_back({budget_all_name, everything});
  return sources;
}

}  // namespace

checked<std::vector<budget_source>> budget_sources(const scene_config& all) {
  std::vector<budget_source> sources = source_scenes(all);
  for (const budget_source& source : sources)
    if (checked<void> valid = validate(source.scene); !valid.ok())
      return diagnostic{"budget",
                        "the " + source.name + " source's scene cannot be simulated (--" +
                            valid.error().option + ": " + valid.error().message + ")",
                        {}};
  return sources;
}

}  // namespace conescan::scene
