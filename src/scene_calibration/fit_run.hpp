// The one fit flow, from a checked plan (fit_request.hpp: build_fit_plan) to its result, that
// conescan-fit (apps/conescan-fit/main.cpp) and conescan.fit / conescan.predict
// (python/src/fit.cpp) both run: the programs parse and check their options into a fit_plan, call
// these, and write the structs they return (calibration/fit_json.hpp, report.hpp). Telemetry comes
// in as the file of --telemetry or as columns in memory (conescan.fit's arrays), read by the one
// reader (calibration/telemetry.hpp); the fit's settings (loss, iterations, threads) are the
// plan's.
//
//   checked<fit_plan> plan = build_fit_plan(entries);                 // refusals: exit 2
//   if (plan.value().request.predict) return write(run_design(plan.value()));
//   checked<telemetry> data = read_fit_telemetry(plan.value());       // the --telemetry file
//   checked<fit_outcome> outcome = run_fit(plan.value(), data.value());
//   // fit_result: converged; unconverged_fit: its last state, never an estimate (exit 1)
#pragma once

#include <string>

#include "calibration/estimator.hpp"
#include "calibration/telemetry.hpp"
#include "scene_calibration/fit_request.hpp"
#include "scene_calibration/scene_fit.hpp"

namespace conescan::calibration {

/// The telemetry of the file the plan names (--telemetry; built with telemetry_input::file_option),
/// read for the plan's scene (its heads, its time stamps: scene_time_stamps). Errors (option
/// "telemetry", exit 2): the file's, naming it, the line and the column (telemetry.hpp); a plan
/// without a telemetry file (--predict, or built for columns). Running out of memory throws
/// text::out_of_memory_reading naming the file.
checked<telemetry> read_fit_telemetry(const fit_plan& plan);

/// The telemetry of `columns` (conescan.fit's arrays; a plan built with
/// telemetry_input::in_memory), read as the file would be, `name` where a file's name stands
/// ("<array>"): the same checks and messages (read_telemetry_columns).
checked<telemetry> read_fit_telemetry(const fit_plan& plan, const telemetry_columns& columns,
                                      const std::string& name);

/// Fits the plan's free parameters to `data` (fit_scene) with the plan's loss, iteration limit
/// and threads; after a converged fit, each measurement's residuals to `each_residual` (when
/// set), on the caller's thread. Returns the converged fit_result or the unconverged_fit (its
/// last state). Errors (bad input, exit 2): fit_scene's (scene_fit.hpp).
checked<fit_outcome> run_fit(const fit_plan& plan, const telemetry& data,
                             const scene_residual_sink& each_residual = {});

/// The plan's experiment design (--predict): the 1 sigma its free parameters would reach for the
/// scene as planned (predict_scene), with the plan's threads. Errors (exit 2): predict_scene's.
checked<design_result> run_design(const fit_plan& plan);

}  // namespace conescan::calibration
