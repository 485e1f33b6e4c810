#include "scene_calibration/scene_fit.hpp"

#include "scene/truth_source.hpp"
#include "scene_calibration/scene_model.hpp"
#include "sources/time_scales.hpp"

namespace conescan::calibration {

telemetry_time_stamps scene_time_stamps(const scene::scene_config& scene) {
  // The epoch of a scene whose files were read (every planned scene), else the default one.
  const sources::instant epoch =
      scene.files
          ? scene.files->epoch
          : sources::parse_epoch(scene::default_epoch_utc, sources::time_scale::utc).value();
  return {[epoch](std::string_view utc) -> checked<double> {
            checked<sources::instant> t = sources::parse_epoch(utc, sources::time_scale::utc);
            if (!t.ok()) return t.error();
            return sources::seconds_between(epoch, t.value());
          },
          [epoch](double week, double seconds) -> checked<double> {
            checked<sources::instant> t = sources::from_gps_week(week, seconds);
            if (!t.ok()) return t.error();
            return sources::seconds_between(epoch, t.value());
          }};
}

parameter_set scene_parameters_freed(const scene::scene_config& scene,
                                     const std::vector<std::size_t>& free) {
  parameter_set p = scene_parameters(scene);
  for (std::size_t i : free) p.free[i] = true;
  return p;
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
  // The model's geometry is indexed by the rows that hold a measurement (a row where every head
  // wrote nan has none): their times, in order, and each observation's row renumbered.
  std::vector<double> times;
  std::vector<std::size_t> data_rows;  // each time's row in the file (0-based, after the header)
  std::vector<observation> observations = data.observations;
  std::size_t last_row = static_cast<std::size_t>(-1);
  for (observation& o : observations) {
    if (o.sample.row != last_row) {
      last_row = o.sample.row;
      times.push_back(o.sample.t_s);
      data_rows.push_back(o.sample.row);
    }
    o.sample.row = times.size() - 1;
  }
  checked<scene_model> model = scene_model::of(scene, times);
  if (!model.ok()) {
    diagnostic e = std::move(model).error();
    // scene_truth_at names a time by its index among `times`: name the file's line instead
    // (line 1 is the header).
    if (e.option == "telemetry" && e.where.line > 0 && e.where.line <= data_rows.size()) {
      e.where.file = data.file;
      e.where.line = data_rows[e.where.line - 1] + 2;
    }
    return e;
  }
  const forward_model_of<scene_model> wrapped(std::move(model).value());
  return fit(
      {&wrapped, scene_parameters_freed(scene, free), std::move(observations), scene_noise(scene)},
      options);
}

checked<design_result> predict_scene(const scene::scene_config& scene,
                                     const std::vector<std::size_t>& free, int threads) {
  const std::uint64_t rows = scene::row_count(scene);
  std::vector<double> times(rows);
  for (std::uint64_t k = 0; k < rows; ++k)  // MODEL §3: a product, never a sum
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
