#include "scene/budget.hpp"

#include "scene/head_spec.hpp"
#include "scene/scene_earth.hpp"
#include "scene/scene_validation.hpp"

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
  for (head_config& h : quiet.heads)
    for (const physics_step step :
         {physics_step::field, physics_step::detector, physics_step::locator})
      copy_physics_step(h, default_head, step);
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

// The user's limb on a pencil beam without lag (MODEL §12): the quiet scene with the horizon the
// processing assumes as given, the radiance profile (delta50, H, the disk, the season term) and
// each head's locator and threshold. The horizon-height source is this scene; the field-of-view
// and detector-lag sources add their effect to it, so each runs where the user's heads look.
scene_config limb_scene(const scene_config& quiet, const scene_config& all) {
  scene_config limb = quiet;
  limb.processing_horizon_km = all.processing_horizon_km;
  limb.radiance_scale_km = all.radiance_scale_km;
  limb.radiance_offset_km = all.radiance_offset_km;
  limb.radiance_disk = all.radiance_disk;
  limb.radiance_season = all.radiance_season;
  for (std::size_t k = 0; k < limb.heads.size(); ++k)
    copy_physics_step(limb.heads[k], all.heads[k], physics_step::locator);
  return limb;
}

// The budget's list as it is built: each source a base scene (the quiet one, or the user's limb)
// with that source switched on.
struct source_list {
  const scene_config& all;
  const scene_config quiet;
  const scene_config limb;
  std::shared_ptr<const source_files> files;  // the user's scene's, shared by every source
  std::vector<budget_source> sources;
  std::optional<std::size_t> limb_source;  // the horizon-height source's index, when it is on

  template <class SwitchOn>
  void add_to(const scene_config& base, const char* name, SwitchOn&& switch_on,
              std::optional<std::size_t> baseline = std::nullopt) {
    scene_config s = base;
    switch_on(s);
    sources.push_back({name, {s, files}, baseline});
  }
  template <class SwitchOn>
  void add(const char* name, SwitchOn&& switch_on) {
    add_to(quiet, name, switch_on);
  }
  // Each head's values of `all` copied by `copy(quiet's head, all's head)`.
  template <class Copy>
  void add_per_head(const char* name, Copy&& copy) {
    add(name, [&](scene_config& s) { copy_heads(s, copy); });
  }
  // On the user's limb, measured from the horizon-height source when it is on (the limb's own
  // error is that source's): what the effect adds where the heads look.
  template <class Copy>
  void add_per_head_on_limb(const char* name, Copy&& copy) {
    add_to(
        limb, name, [&](scene_config& s) { copy_heads(s, copy); }, limb_source);
  }

 private:
  template <class Copy>
  void copy_heads(scene_config& s, Copy&& copy) const {
    for (std::size_t k = 0; k < s.heads.size(); ++k) copy(s.heads[k], all.heads[k]);
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

// The Earth's shape, the limb's height against the horizon the processing assumes, and the
// apparent horizon's latitude and season terms.
void add_earth_sources(source_list& list, const head_sources_on& on) {
  const scene_config& all = list.all;
  if (all.earth == earth_model::wgs84)
    list.add("oblateness", [&](scene_config& s) {
      s.earth = earth_model::wgs84;
      s.radius_km.reset();
      s.processing_radius = all.processing_radius;
      s.processing_radius_km = all.processing_radius_km;
    });
  // Where the heads see the horizon (the surface's height, the radiance's shape, the locator)
  // against where the processing assumes it: one source. As two (the height, then the radiance
  // on the truth's horizon), a CO2 limb the processing models (delta50 = 40 km, processing
  // horizon 40 km) showed two errors of 2.2 deg that cancel.
  const bool height_differs =
      all.processing_horizon_km && *all.processing_horizon_km != all.horizon_km;
  if (height_differs || on.radiant) {
    list.limb_source = list.sources.size();
    list.add_to(list.limb, "horizon-height", [](scene_config&) {});
  }
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

// The sensor physics that acts on the limb (MODEL §12): the field (its shape too) and the
// detector's lag, each on the user's limb and measured from it.
void add_physics_sources(source_list& list, const head_sources_on& on) {
  if (on.field)
    list.add_per_head_on_limb("field-of-view", [](head_config& h, const head_config& given) {
      copy_physics_step(h, given, physics_step::field);
    });
  if (on.lagged)
    list.add_per_head_on_limb("detector-lag", [](head_config& h, const head_config& given) {
      copy_physics_step(h, given, physics_step::detector);
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

std::vector<budget_source> source_scenes(const loaded_scene& user) {
  const scene_config& all = user.config;
  const scene_config quiet = quiet_scene(all);
  source_list list{all, quiet, limb_scene(quiet, all), user.files, {}, std::nullopt};
  const head_sources_on on(all);
  add_head_geometry(list, on);
  add_earth_sources(list, on);
  add_physics_sources(list, on);
  add_measurement_sources(list, on);
  scene_config everything = all;
  everything.model = forward_model::scan;
  list.sources.push_back({budget_all_name, {everything, user.files}, std::nullopt});
  return list.sources;
}

}  // namespace

checked<std::vector<budget_source>> budget_sources(const loaded_scene& all) {
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
