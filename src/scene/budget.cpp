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

  bool misaligned = false, noisy = false, stepped = false, biased = false;
  for (const head_config& h : all.heads) {
    misaligned = misaligned || h.sigma_deg > 0;
    biased = biased || h.dgamma_deg != 0 || h.bias_in_deg != 0 || h.bias_out_deg != 0;
    noisy = noisy || h.noise_deg > 0;
    stepped = stepped || h.lsb_deg > 0;
  }
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
