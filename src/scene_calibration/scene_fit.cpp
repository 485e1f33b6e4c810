#include "scene_calibration/scene_fit.hpp"

#include <algorithm>
#include <iterator>
#include <variant>

#include "calibration/report.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_physics.hpp"
#include "scene/scene_validation.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "scene_calibration/scene_model.hpp"
#include "sources/time_scales.hpp"
#include "text/number_text.hpp"

namespace conescan::calibration {

telemetry_time_stamps scene_time_stamps(const scene::loaded_scene& scene) {
  // The rows must lie in the scene's span: telemetry of another time fitted to this scene's
  // geometry converges to a wrong answer (GPS weeks modulo 1024: a 16.9 deg misalignment).
  const scene::scene_config& s = scene.config;
  telemetry_span span{0, scene::scene_duration_s(scene),
                      s.duration_s ? "--duration-s" : "--orbits " + text::shortest_text(s.orbits)};
  // The epoch of a scene whose files were read (every planned scene), one the user gave (--epoch,
  // or the orbit file's): none with MODEL §10's default epoch, and the reader refuses absolute
  // times (the default of 2000 would put telemetry of 2026 26 years past the scene).
  if (!scene.files || scene.files->default_epoch) return {{}, {}, std::move(span)};
  const sources::instant epoch = scene.files->epoch;
  return {[epoch](std::string_view utc) -> checked<double> {
            checked<sources::instant> t = sources::parse_epoch(utc, sources::time_scale::utc);
            if (!t.ok()) return t.error();
            return sources::seconds_between(epoch, t.value());
          },
          [epoch](double week, double seconds) -> checked<double> {
            checked<sources::instant> t = sources::from_gps_week(week, seconds);
            if (!t.ok()) return t.error();
            return sources::seconds_between(epoch, t.value());
          },
          std::move(span)};
}

namespace {

/// The scene with parameter `index` set to `value` (scene_parameters' inverse).
void set_parameter(scene::scene_config& s, std::size_t index, double value) {
  const std::size_t heads = s.heads.size();
  if (index >= head_parameter_count * heads) {
    double* earth[] = {&s.horizon_km, &s.horizon_pole_km, &s.horizon_shift_km,
                       &s.radiance_offset_km, &s.radiance_scale_km};
    static_assert(std::size(earth) == earth_parameter_count);
    *earth[index - head_parameter_count * heads] = value;
    return;
  }
  const scene::head_key& key = head_parameter_key(head_parameter(index % head_parameter_count));
  s.heads[index / head_parameter_count].*key.field = value;
}

/// A warning for each determined estimate that the scene's own checks refuse (a horizon below
/// the surface, a negative sigma, a cone angle out of (sigma, 90) deg, ...): the scene with that
/// one estimate put in, validated as the simulation validates it.
void warn_outside_domain(const scene::loaded_scene& scene, fit_result& r) {
  for (const parameter_estimate& e : r.uncertainty.reported) {
    if (!e.determined) continue;
    scene::loaded_scene s = scene;
    set_parameter(s.config, e.index, e.estimate);
    if (const checked<void> valid = scene::validate(s); !valid.ok())
      r.warnings.push_back(e.name + " = " + short_number(e.estimate) + " " + e.unit +
                           " leaves the parameter's domain: " + valid.error().text());
  }
}

std::vector<free_parameter> global(const std::vector<std::size_t>& indices) {
  std::vector<free_parameter> free;
  for (std::size_t i : indices) free.push_back({i, 0.0});
  return free;
}

// The heads' statuses at the telemetry's rows by the scene's own pipeline (--intrusions, MODEL
// §13): which measurements a body blinds. Rows are those with any sample, measured or nan.
class row_statuses {
 public:
  static checked<row_statuses> of(const scene::loaded_scene& scene, const telemetry& data,
                                  int threads) {
    row_statuses r;
    r.heads_ = scene.config.heads.size();
    // Both lists are in row order; their rows merged, in order (increasing time).
    std::size_t i = 0, j = 0;
    const auto& measured = data.observations;
    const auto& unmeasured = data.unmeasured;
    while (i < measured.size() || j < unmeasured.size()) {
      const bool take_measured =
          j == unmeasured.size() ||
          (i < measured.size() && measured[i].sample.row <= unmeasured[j].row);
      const telemetry_sample& s = take_measured ? measured[i++].sample : unmeasured[j++];
      if (r.rows_.empty() || r.rows_.back() != s.row) {
        r.rows_.push_back(s.row);
        r.times_s_.push_back(s.t_s);
      }
    }
    checked<std::vector<status>> statuses = scene_head_statuses_at(scene, r.times_s_, threads);
    if (!statuses.ok()) {
      diagnostic e = std::move(statuses).error();
      // The index among the times, as the file's line (line 1 is the header).
      if (e.option == "telemetry" && e.where.line > 0 && e.where.line <= r.rows_.size()) {
        e.where.file = data.file;
        e.where.line = r.rows_[e.where.line - 1] + 2;
      }
      return e;
    }
    r.statuses_ = std::move(statuses).value();
    return r;
  }

  status at(const telemetry_sample& s) const {
    const auto row = std::lower_bound(rows_.begin(), rows_.end(), s.row);
    return statuses_[static_cast<std::size_t>(row - rows_.begin()) * heads_ + s.head];
  }

 private:
  std::size_t heads_ = 0;
  std::vector<std::size_t> rows_;
  std::vector<double> times_s_;
  std::vector<status> statuses_;  // row-major: rows_[i], head h at [i * heads_ + h]
};

// With --intrusions: the measurements a body blinds left out of `observations`, and every
// blinded sample (measured or nan) counted per head and body.
checked<blinded_rows> leave_out_blinded(const scene::loaded_scene& scene, const telemetry& data,
                                        std::vector<observation>& observations, int threads) {
  checked<row_statuses> statuses = row_statuses::of(scene, data, threads);
  if (!statuses.ok()) return statuses.error();
  const std::size_t heads = scene.config.heads.size();
  blinded_rows counts{std::vector<std::size_t>(heads, 0), std::vector<std::size_t>(heads, 0)};
  const auto count = [&](const telemetry_sample& s) {
    const status state = statuses.value().at(s);
    if (state == status::sun) ++counts.sun[s.head];
    if (state == status::moon) ++counts.moon[s.head];
    return state == status::sun || state == status::moon;
  };
  for (const telemetry_sample& s : data.unmeasured) count(s);
  std::erase_if(observations, [&](const observation& o) { return count(o.sample); });
  return counts;
}

// The sensor physics' parameters can be free only where the scene runs MODEL §12's chain and
// where the chain depends on them smoothly from the start: a lag at tau = 0 is none (the chain's
// derivative there is the pencil's, 0), a step edge (H = 0) has no derivative in H, a slope or
// normalised locator has no level to fit (the normalised fraction is the processing's own).
checked<void> check_free_physics(const scene::scene_config& scene,
                                 const std::vector<free_parameter>& free) {
  const std::size_t heads = scene.heads.size();
  const auto refuse = [&](std::size_t index, const std::string& why) {
    return diagnostic{"free", parameter_name(index, heads) + " is free but " + why};
  };
  for (const free_parameter& f : free) {
    if (!is_physics_parameter(f.index, heads)) continue;
    if (f.index >= head_parameter_count * heads) {
      if (!scene::any_physics(scene))
        return refuse(f.index,
                      "no head runs the sensor physics (MODEL §12): give the heads their physics "
                      "keys (spin-hz=, tau-ms=, fov=, ...) or the --radiance-* options");
      if (f.index == parameter_index(heads, earth_parameter::radiance_scale) &&
          !(scene.radiance_scale_km > 0))
        return refuse(f.index,
                      "the limb is a step edge (--radiance-scale-km 0), with no derivative in "
                      "its scale height: start from a scale height > 0");
      continue;
    }
    const std::size_t k = f.index / head_parameter_count;
    const scene::head_config& h = scene.heads[k];
    const std::string head = "head " + std::to_string(k + 1);
    if (!scene::physics_on(scene, h))
      return refuse(f.index, head +
                                 " runs no sensor physics (MODEL §12): give it its physics keys "
                                 "(spin-hz=, tau-ms=, ...)");
    if (f.index == parameter_index(k, head_parameter::tau_ms) && !(h.tau_ms > 0))
      return refuse(f.index, head +
                                 " starts without lag (tau-ms=0, where the lag has no "
                                 "derivative): give it a starting tau-ms= > 0 and its spin-hz=");
    if (f.index == parameter_index(k, head_parameter::threshold) &&
        h.locator != locator_kind::fixed)
      return refuse(f.index,
                    head +
                        " has no fixed locator: only a fixed level (locator=fixed) is fitted; a "
                        "normalised fraction is the processing's own setting, a slope has none");
  }
  return success();
}

}  // namespace

parameter_set scene_parameters_freed(const scene::scene_config& scene,
                                     const std::vector<free_parameter>& free) {
  parameter_set p = scene_parameters(scene);
  free_parameters(p, free);
  return p;
}

parameter_set scene_parameters_freed(const scene::scene_config& scene,
                                     const std::vector<std::size_t>& free) {
  return scene_parameters_freed(scene, global(free));
}

checked<fit_outcome> fit_scene(const scene::loaded_scene& scene, const telemetry& data,
                               const std::vector<std::size_t>& free, const fit_options& options) {
  return fit_scene(scene, data, global(free), options);
}

checked<fit_outcome> fit_scene(const scene::loaded_scene& scene, const telemetry& data,
                               const std::vector<free_parameter>& free,
                               const fit_options& options) {
  return fit_scene(scene, data, free, options, {});
}

checked<fit_outcome> fit_scene(const scene::loaded_scene& loaded, const telemetry& data,
                               const std::vector<free_parameter>& free, const fit_options& options,
                               const scene_residual_sink& each_residual) {
  const scene::scene_config& scene = loaded.config;
  if (checked<void> physics = check_free_physics(scene, free); !physics.ok())
    return physics.error();
  // With --intrusions the measurements a body blinds are left out: the fit borrows a copy
  // without them; otherwise the telemetry's own (a month is not copied).
  std::span<const observation> observations = data.observations;
  std::vector<observation> unblinded;
  blinded_rows blinded;
  if (scene.intrusions) {
    unblinded = data.observations;
    checked<blinded_rows> left_out = leave_out_blinded(loaded, data, unblinded, options.threads);
    if (!left_out.ok()) return std::move(left_out).error();
    blinded = std::move(left_out).value();
    observations = unblinded;
  }
  checked<scene_model> model = scene_model::of_telemetry(loaded, data, options.threads);
  if (!model.ok()) return std::move(model).error();
  const forward_model_of<scene_model> wrapped(std::move(model).value());
  fit_options with_sink = options;
  if (each_residual)
    with_sink.each_residual = [&](const residual_row& r) {
      each_residual(r, wrapped.model().latitude_deg(r.measured->sample.row));
    };
  checked<fit_outcome> outcome = fit(
      {&wrapped, scene_parameters_freed(scene, free), observations, scene_noise(scene)}, with_sink);
  if (outcome.ok()) {
    std::visit([&](auto& result) { result.blinded = blinded; }, outcome.value());
    if (auto* r = std::get_if<fit_result>(&outcome.value())) warn_outside_domain(loaded, *r);
  }
  return outcome;
}

checked<design_result> predict_scene(const scene::loaded_scene& scene,
                                     const std::vector<std::size_t>& free, int threads) {
  return predict_scene(scene, global(free), threads);
}

checked<design_result> predict_scene(const scene::loaded_scene& loaded,
                                     const std::vector<free_parameter>& free, int threads) {
  const scene::scene_config& scene = loaded.config;
  if (checked<void> physics = check_free_physics(scene, free); !physics.ok())
    return physics.error();
  const std::uint64_t rows = scene::row_count(loaded);
  std::vector<double> times(rows);
  for (std::uint64_t k = 0; k < rows; ++k)  // MODEL §3: a product, never a sum
    times[k] = static_cast<double>(k) * scene.step_s;
  checked<scene_model> model = scene_model::of(loaded, times);
  if (!model.ok()) return std::move(model).error();
  const forward_model_of<scene_model> wrapped(std::move(model).value());
  std::vector<telemetry_sample> samples;
  samples.reserve(rows * scene.heads.size());
  for (std::uint64_t k = 0; k < rows; ++k)
    for (std::size_t h = 0; h < scene.heads.size(); ++h)
      samples.push_back({static_cast<std::size_t>(k), times[k], h});
  blinded_rows blinded;
  if (scene.intrusions) {  // the planned samples a body will blind (MODEL §13) left out
    checked<std::vector<status>> statuses = scene_head_statuses_at(loaded, times, threads);
    if (!statuses.ok()) return std::move(statuses).error();
    blinded = {std::vector<std::size_t>(scene.heads.size(), 0),
               std::vector<std::size_t>(scene.heads.size(), 0)};
    std::erase_if(samples, [&](const telemetry_sample& s) {
      const status state = statuses.value()[s.row * scene.heads.size() + s.head];
      if (state == status::sun) ++blinded.sun[s.head];
      if (state == status::moon) ++blinded.moon[s.head];
      return state == status::sun || state == status::moon;
    });
  }
  checked<design_result> design = predict_uncertainty(wrapped, scene_parameters_freed(scene, free),
                                                      samples, scene_noise(scene), threads);
  if (design.ok()) design.value().blinded = blinded;
  return design;
}

}  // namespace conescan::calibration
