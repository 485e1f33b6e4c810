// A calibration of a scene (MODEL §11): conescan-fit's work, callable from tests and
// benchmarks without the program. The scene (validated, scene_plan.hpp) supplies the orbit, the
// reference attitude, the heads' nominal mounting, the Earth and the stated noise; its heads'
// sigma, phase, dgamma, bias-in, bias-out and its horizon-km, horizon-pole-km, horizon-shift-km
// are the start of the free parameters and the values of the held ones.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/telemetry.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene/scene_plan.hpp"

namespace conescan::calibration {

/// Fits the parameters `free` (parse_free_selection: global or drifting) to the telemetry, and
/// warns about each determined estimate (a drifting one's in each segment) that the scene's own
/// checks refuse. Errors (exit 2): those of scene_model::of and of fit().
checked<fit_outcome> fit_scene(const scene::loaded_scene& scene, const telemetry& data,
                               const std::vector<free_parameter>& free, const fit_options& options);
/// A measurement's residuals at a scene fit's solution and the satellite's geocentric latitude
/// (deg) at its row: what a residuals file writes.
using scene_residual_sink = std::function<void(const residual_row&, double latitude_deg)>;

/// The same, each measurement's residuals handed to `each_residual` after a converged fit.
checked<fit_outcome> fit_scene(const scene::loaded_scene& scene, const telemetry& data,
                               const std::vector<free_parameter>& free, const fit_options& options,
                               const scene_residual_sink& each_residual);
/// The same with global parameters (indices, parse_free_list).
checked<fit_outcome> fit_scene(const scene::loaded_scene& scene, const telemetry& data,
                               const std::vector<std::size_t>& free, const fit_options& options);

/// Experiment design for the scene as planned: its time grid (--step-s, --orbits or
/// --duration-s), every head at every row, the stated noise; the 1 sigma of the parameters
/// `free` from the Fisher information at the scene's values (predict_uncertainty).
checked<design_result> predict_scene(const scene::loaded_scene& scene,
                                     const std::vector<free_parameter>& free, int threads = 2);
checked<design_result> predict_scene(const scene::loaded_scene& scene,
                                     const std::vector<std::size_t>& free, int threads = 2);

/// Telemetry's absolute time stamps (utc; gps_week and gps_s) as seconds from the scene's epoch
/// (its files read: scene_plan), through the sources library's time scales, leap seconds
/// included (ERFA). The rule: the engine (calibration/) reads the columns and knows no calendar;
/// this tier, which knows the scene, gives it the conversion. And the span the rows must lie in:
/// the scene's, t_s 0 to its duration.
telemetry_time_stamps scene_time_stamps(const scene::loaded_scene& scene);

/// The scene's parameters with `free` freed.
parameter_set scene_parameters_freed(const scene::scene_config& scene,
                                     const std::vector<free_parameter>& free);
parameter_set scene_parameters_freed(const scene::scene_config& scene,
                                     const std::vector<std::size_t>& free);

}  // namespace conescan::calibration
