#include "scene_calibration/fit_run.hpp"

#include "text/out_of_memory.hpp"

namespace conescan::calibration {

checked<telemetry> read_fit_telemetry(const fit_plan& plan) {
  if (!plan.request.telemetry)
    return diagnostic{"telemetry", "no telemetry file in the plan (--predict, or columns)"};
  const std::string& path = *plan.request.telemetry;
  return text::naming_input("telemetry", path, [&] {
    return read_telemetry_file(path, plan.scene.config.heads.size(), scene_time_stamps(plan.scene));
  });
}

checked<telemetry> read_fit_telemetry(const fit_plan& plan, const telemetry_columns& columns,
                                      const std::string& name) {
  return read_telemetry_columns(columns, name, plan.scene.config.heads.size(),
                                scene_time_stamps(plan.scene));
}

checked<fit_outcome> run_fit(const fit_plan& plan, const telemetry& data,
                             const scene_residual_sink& each_residual) {
  fit_options options;
  options.loss = plan.request.loss;
  options.max_iterations = plan.request.max_iterations;
  options.threads = plan.threads;
  return fit_scene(plan.scene, data, plan.free, options, each_residual);
}

checked<design_result> run_design(const fit_plan& plan) {
  return predict_scene(plan.scene, plan.free, plan.threads);
}

}  // namespace conescan::calibration
