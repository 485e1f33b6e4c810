#include "scene/budget.hpp"

#include "scene/scene_earth.hpp"

namespace conescan::scene {

namespace {

// The common ground of the single-source runs: the scan model on the sphere the processing
// assumes, with every error source off.
scene_config quiet_scene(const scene_config& all) {
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
  return quiet;
}

// Which of the heads' own sources are on in a scene (any head).
struct head_sources_on {
  bool misaligned = false, noisy = false, stepped = false, biased = false;
  bool field = false, lagged = false, radiant = false;

  explicit head_sources_on(const scene_config& all) {
    const scene_config defaults;
    const head_config default_head;
    bool located = false;
    for (const head_config& h : all.heads) {
      misaligned = misaligned || h.sigma_deg > 0;
      biased = biased || h.dgamma_deg != 0 || h.bias_in_deg != 0 || h.bias_out_deg != 0;
      noisy = noisy || h.noise_deg > 0;
      stepped = stepped || h.lsb_deg > 0;
      field = field || h.fov_deg > 0;
      lagged = lagged || h.tau_ms > 0;
      located =
          located || h.locator != default_head.locator || h.threshold != default_head.threshold;
    }
    radiant = located || all.radiance_offset_km != defaults.radiance_offset_km ||
              all.radiance_disk != defaults.radiance_disk ||
              all.radiance_season != defaults.radiance_season;
  }
};

// The budget's list as it is built: each source the quiet scene with that source switched on.
struct source_list {
  const scene_config& all;
  const scene_config quiet;
  std::vector<budget_source> sources;

  template <class SwitchOn>
  void add(const char* name, SwitchOn&& switch_on) {
    scene_config s = quiet;
    switch_on(s);
    sources.push_back({name, s});
  }
  // Each head's values of `all` copied by `copy(quiet's head, all's head)`.
  template <class Copy>
  void add_per_head(const char* name, Copy&& copy) {
    add(name, [&](scene_config& s) {
      for (std::size_t k = 0; k < s.heads.size(); ++k) copy(s.heads[k], all.heads[k]);
    });
  }
};

// The heads' geometry: the misalignment and the fixed biases (the cone-angle bias and the
// crossing biases together).
void add_head_geometry(source_list& list, const head_sources_on& on) {
  if (on.misaligned)
    list.add_per_head("misalignment", [](head_config& h, const head_config& given) {
      h.sigma_deg = given.sigma_deg;
    });
  if (on.biased)
    list.add_per_head("head-biases", [](head_config& h, const head_config& given) {
      h.dgamma_deg = given.dgamma_deg;
      h.bias_in_deg = given.bias_in_deg;
      h.bias_out_deg = given.bias_out_deg;
    });
}

// The Earth's shape and the horizon the processing assumes.
void add_earth_sources(source_list& list) {
  const scene_config& all = list.all;
  if (all.earth == earth_model::wgs84)
    list.add("oblateness", [&](scene_config& s) {
      s.earth = earth_model::wgs84;
      s.radius_km.reset();
      s.processing_radius = all.processing_radius;
      s.processing_radius_km = all.processing_radius_km;
    });
  if (all.processing_horizon_km && *all.processing_horizon_km != all.horizon_km)
    list.add("horizon-height",
             [&](scene_config& s) { s.processing_horizon_km = all.processing_horizon_km; });
  // The latitude and season terms on a sphere of radius a + h0: the apparent surface machinery
  // with the geodetic flattening switched off, processed on that sphere.
  auto apparent_sphere = [](scene_config& s) {
    s.earth = earth_model::wgs84;
    s.radius_km.reset();
    s.geodetic_flattening = false;
    s.processing_radius = processing_radius_kind::equatorial;
  };
  if (all.horizon_pole_km != 0)
    list.add("horizon-pole", [&](scene_config& s) {
      apparent_sphere(s);
      s.horizon_pole_km = all.horizon_pole_km;
    });
  if (all.horizon_shift_km != 0)
    list.add("horizon-season", [&](scene_config& s) {
      apparent_sphere(s);
      s.horizon_shift_km = all.horizon_shift_km;
    });
}

// The sensor physics (MODEL §12), each on the profile's scale height as given: the field (its
// shape too), the detector's lag, and what the radiance and the locator make of the horizon (the
// 50 % point's offset, the disk, the season term, the locator and its threshold: the height the
// pulse is cut at, and how it varies).
void add_physics_sources(source_list& list, const head_sources_on& on) {
  const scene_config& all = list.all;
  auto on_profile = [&](scene_config& s, auto&& copy) {
    s.radiance_scale_km = all.radiance_scale_km;
    for (std::size_t k = 0; k < s.heads.size(); ++k) copy(s.heads[k], all.heads[k]);
  };
  if (on.field)
    list.add("field-of-view", [&](scene_config& s) {
      on_profile(s, [](head_config& h, const head_config& given) {
        h.fov_deg = given.fov_deg;
        h.shape = given.shape;
      });
    });
  if (on.lagged)
    list.add("detector-lag", [&](scene_config& s) {
      on_profile(s, [](head_config& h, const head_config& given) {
        h.spin_hz = given.spin_hz;
        h.tau_ms = given.tau_ms;
      });
    });
  if (on.radiant)
    list.add("radiance", [&](scene_config& s) {
      s.radiance_offset_km = all.radiance_offset_km;
      s.radiance_disk = all.radiance_disk;
      s.radiance_season = all.radiance_season;
      on_profile(s, [](head_config& h, const head_config& given) {
        h.locator = given.locator;
        h.threshold = given.threshold;
      });
    });
}

// What the measurement adds: the detector's noise and the telemetry's steps.
void add_measurement_sources(source_list& list, const head_sources_on& on) {
  if (on.noisy)
    list.add_per_head(
        "noise", [](head_config& h, const head_config& given) { h.noise_deg = given.noise_deg; });
  if (on.stepped)
    list.add_per_head("quantisation",
                      [](head_config& h, const head_config& given) { h.lsb_deg = given.lsb_deg; });
}

std::vector<budget_source> source_scenes(const scene_config& all) {
  source_list list{all, quiet_scene(all), {}};
  const head_sources_on on(all);
  add_head_geometry(list, on);
  add_earth_sources(list);
  add_physics_sources(list, on);
  add_measurement_sources(list, on);
  scene_config everything = all;
  everything.model = forward_model::scan;
  list.sources.push_back({budget_all_name, everything});
  return list.sources;
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
