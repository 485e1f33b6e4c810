#include "scene_calibration/scene_fit.hpp"

#include "calibration/report.hpp"
#include "scene_calibration/scene_model.hpp"

namespace conescan::calibration {

namespace {

/// The scene with parameter `index` set to `value` (scene_parameters' inverse).
void set_parameter(scene::scene_config& s, std::size_t index, double value) {
  const std::size_t heads = s.heads.size();
  if (index >= head_parameter_count * heads) {
    double* earth[] = {&s.horizon_km, &s.horizon_pole_km, &s.horizon_shift_km};
    *earth[index - head_parameter_count * heads] = value;
    return;
  }
  scene::head_config& h = s.heads[index / head_parameter_count];
  double* head[] = {&h.sigma_deg, &h.phase_deg, &h.dgamma_deg, &h.bias_in_deg, &h.bias_out_deg};
  *head[index % head_parameter_count] = value;
}

/// A warning for each determined estimate that the scene's own checks refuse (a horizon below
/// the surface, a negative sigma, a cone angle out of (sigma, 90) deg, ...): the scene with that
/// one estimate put in, validated as the simulation validates it.
void warn_outside_domain(const scene::scene_config& scene, fit_result& r) {
  for (const parameter_estimate& e : r.uncertainty.reported) {
    if (!e.determined) continue;
    scene::scene_config s = scene;
    set_parameter(s, e.index, e.estimate);
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

std::string single_scene_problem(const scene::scene_request& r) {
  if (r.sweep) return "--sweep: conescan-fit fits one scene";
  if (r.budget) return "--budget: conescan-fit fits one scene";
  if (r.summary) return "--summary: conescan-fit prints its own table";
  if (r.scene.runs != 1) return "--runs: conescan-fit fits one telemetry";
  if (r.apply_fit) return "--apply: conescan-sim corrects with a fit; conescan-fit makes one";
  return {};
}

checked<fit_outcome> fit_scene(const scene::scene_config& scene, const telemetry& data,
                               const std::vector<std::size_t>& free, const fit_options& options) {
  return fit_scene(scene, data, global(free), options);
}

checked<fit_outcome> fit_scene(const scene::scene_config& scene, const telemetry& data,
                               const std::vector<free_parameter>& free,
                               const fit_options& options) {
  return fit_scene(scene, data, free, options, {});
}

checked<fit_outcome> fit_scene(const scene::scene_config& scene, const telemetry& data,
                               const std::vector<free_parameter>& free, const fit_options& options,
                               const scene_residual_sink& each_residual) {
  checked<scene_model> model = scene_model::of_telemetry(scene, data, options.threads);
  if (!model.ok()) return std::move(model).error();
  const forward_model_of<scene_model> wrapped(std::move(model).value());
  fit_options with_sink = options;
  if (each_residual)
    with_sink.each_residual = [&](const residual_row& r) {
      each_residual(r, wrapped.model().latitude_deg(r.measured->sample.row));
    };
  checked<fit_outcome> outcome =
      fit({&wrapped, scene_parameters_freed(scene, free), data.observations, scene_noise(scene)},
          with_sink);
  if (outcome.ok())
    if (auto* r = std::get_if<fit_result>(&outcome.value())) warn_outside_domain(scene, *r);
  return outcome;
}

checked<design_result> predict_scene(const scene::scene_config& scene,
                                     const std::vector<std::size_t>& free, int threads) {
  return predict_scene(scene, global(free), threads);
}

checked<design_result> predict_scene(const scene::scene_config& scene,
                                     const std::vector<free_parameter>& free, int threads) {
  const std::uint64_t rows = scene::row_count(scene);
  std::vector<double> times(rows);
  for (std::uint64_t k = 0; k < rows; ++k)  // SPEC §3: a product, never a sum
    times[k] = static_cast<double>(k) * scene.step_s;
  checked<scene_model> model = scene_model::of(scene, times);
  if (!model.ok()) return std::move(model).error();
  const forward_model_of<scene_model> wrapped(std::move(model).value());
  std::vector<telemetry_sample> samples;
  samples.reserve(rows * scene.heads.size());
  for (std::uint64_t k = 0; k < rows; ++k)
    for (std::size_t h = 0; h < scene.heads.size(); ++h)
      samples.push_back({static_cast<std::size_t>(k), times[k], h});
  return predict_uncertainty(wrapped, scene_parameters_freed(scene, free), samples,
                             scene_noise(scene), threads);
}

}  // namespace conescan::calibration
