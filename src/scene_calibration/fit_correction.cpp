#include "scene_calibration/fit_correction.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/layout.hpp"
#include "calibration/telemetry.hpp"
#include "scene/scene_validation.hpp"
#include "scene_calibration/scene_model.hpp"
#include "text/number_text.hpp"
#include "text/out_of_memory.hpp"

namespace conescan::scene {

namespace cal = calibration;

/// A head's fitted values: its model parameters (tau-ms NaN where the fit ran no chain) and its
/// crossing biases.
struct fitted_head {
  cal::head_geometry<double> head;
  double bias_in_deg;
  double bias_out_deg;
};

struct fit_correction::state {
  cal::scene_model model;
  std::vector<fitted_head> fitted;  // per head
  cal::earth_geometry<double> earth{0, 0, 0, 0, 0};
};

namespace {

// A parameter's fitted value (its held value when it was not free), or NaN when undetermined.
double value_of(const cal::fit_result& fit, std::size_t index) {
  const cal::parameter_estimate& p = fit.uncertainty.parameters[index];
  return p.determined ? p.estimate : std::nan("");
}

// Head k's misalignment components (deg): the estimated coordinates when sigma and phase were
// both free (defined even where phi_A is withheld), else from sigma and phase.
bool misalignment_of(const cal::fit_result& fit, std::size_t k, double& x, double& y) {
  const cal::uncertainty_report& u = fit.uncertainty;
  if (const auto i = cal::find_coordinate(u, k, cal::misalignment_axis::x))
    x = u.coordinate_values[*i];
  if (const auto i = cal::find_coordinate(u, k, cal::misalignment_axis::y))
    y = u.coordinate_values[*i];
  if (std::isnan(x) || std::isnan(y)) {
    const double sigma = value_of(fit, cal::parameter_index(k, cal::head_parameter::sigma));
    const double phase_rad = value_of(fit, cal::parameter_index(k, cal::head_parameter::phase)) *
                             cal::radians_per_degree;
    x = sigma * std::cos(phase_rad);
    y = sigma * std::sin(phase_rad);
  }
  return std::isfinite(x) && std::isfinite(y);
}

// What coordinate i must be by the parameters block: the estimate of its parameter, or a
// misalignment component's from the head's sigma and phase (NaN where those are undetermined, or
// for a drifting coordinate: nothing to compare), and the scale of the comparison.
std::pair<double, double> expected_coordinate(const cal::fit_result& fit, std::size_t i) {
  const cal::coordinate_key& key = fit.uncertainty.coordinate_keys[i];
  if (key.segment) return {std::nan(""), 1};
  if (!key.cartesian) {
    const cal::parameter_estimate& p = fit.uncertainty.parameters[key.slot];
    const double expected = p.determined ? p.estimate : std::nan("");
    return {expected, std::max(1.0, std::abs(expected))};
  }
  const std::size_t k = key.slot / cal::head_parameter_count;
  const bool x = key.slot == cal::parameter_index(k, cal::head_parameter::sigma);
  const double sigma = value_of(fit, cal::parameter_index(k, cal::head_parameter::sigma));
  const double phase_rad =
      value_of(fit, cal::parameter_index(k, cal::head_parameter::phase)) * cal::radians_per_degree;
  return {x ? sigma * std::cos(phase_rad) : sigma * std::sin(phase_rad),
          std::max(std::abs(sigma), 1e-300)};
}

// The coordinates block must say what the parameters block says: each coordinate the estimate
// of its parameter, a misalignment's x and y the sigma and phase's (where those are determined).
// An edited file in which they disagree is refused rather than read by one block only. The
// coordinates are taken by their keys (head, parameter), which the reader set from the layout
// after checking every name against it: no name is parsed here.
checked<void> check_coordinates(const cal::fit_result& fit) {
  const cal::uncertainty_report& u = fit.uncertainty;
  for (std::size_t i = 0; i < u.coordinate_keys.size(); ++i) {
    const double value = u.coordinate_values[i];
    if (std::isnan(value)) continue;  // undetermined: nothing to compare
    const auto [expected, scale] = expected_coordinate(fit, i);
    if (std::isnan(expected)) continue;
    // Both blocks are written from one estimate; sigma and phase from x and y round-trip within
    // a few ulp of sigma.
    if (!(std::abs(value - expected) <= 1e-9 * scale))
      return conescan::diagnostic{
          "apply", "coordinate " + u.coordinate_names[i] + " = " + text::shortest_text(value) +
                       " disagrees with the parameters' estimate " + text::shortest_text(expected) +
                       ": the file was edited (write it again with conescan-fit --json)"};
  }
  return success();
}

// The fitted values must make a scene of the model's domain (validate()): a head's misalignment,
// cone-angle and crossing biases, the horizon terms. A value of 1e300 would make every row
// invalid; refused here, naming it.
checked<void> check_domain(const loaded_scene& loaded, const cal::fit_result& fit) {
  const scene_config& scene = loaded.config;
  loaded_scene fitted_scene = loaded;
  scene_config& fitted = fitted_scene.config;
  for (std::size_t k = 0; k < scene.heads.size(); ++k) {
    double x = std::nan(""), y = std::nan("");
    head_config& h = fitted.heads[k];
    if (misalignment_of(fit, k, x, y)) {
      h.sigma_deg = std::hypot(x, y);
      h.phase_deg = std::atan2(y, x) / cal::radians_per_degree;
    }
    for (const cal::head_parameter p :
         {cal::head_parameter::dgamma, cal::head_parameter::bias_in, cal::head_parameter::bias_out,
          cal::head_parameter::tau_ms, cal::head_parameter::threshold})
      if (const double v = value_of(fit, cal::parameter_index(k, p)); !std::isnan(v))
        h.*cal::head_parameter_key(p).field = v;
  }
  const std::size_t heads = scene.heads.size();
  for (const auto& [field, p] :
       {std::pair{&fitted.horizon_km, cal::earth_parameter::horizon},
        std::pair{&fitted.horizon_pole_km, cal::earth_parameter::horizon_pole},
        std::pair{&fitted.horizon_shift_km, cal::earth_parameter::horizon_shift},
        std::pair{&fitted.radiance_offset_km, cal::earth_parameter::radiance_offset},
        std::pair{&fitted.radiance_scale_km, cal::earth_parameter::radiance_scale}})
    if (const double v = value_of(fit, cal::parameter_index(heads, p)); !std::isnan(v)) *field = v;
  checked<void> valid = validate(fitted_scene);
  if (valid.ok()) return valid;
  return conescan::diagnostic{
      "apply", "the fit's estimates are outside the model's domain: " + valid.error().text()};
}

// Head k's fitted values, or `why` says why there is nothing to subtract.
fitted_head fitted_head_of(const cal::fit_result& fit, std::size_t k, const cal::scene_model& model,
                           std::string& why) {
  double x = std::nan(""), y = std::nan("");
  const bool misaligned = misalignment_of(fit, k, x, y);
  const double dgamma = value_of(fit, cal::parameter_index(k, cal::head_parameter::dgamma));
  const double in = value_of(fit, cal::parameter_index(k, cal::head_parameter::bias_in));
  const double out = value_of(fit, cal::parameter_index(k, cal::head_parameter::bias_out));
  if (!misaligned || !std::isfinite(dgamma) || !std::isfinite(in) || !std::isfinite(out))
    why = "the fit leaves a parameter undetermined (unobservable): nothing to subtract";
  // The physics as the fit modelled it: where it ran the chain for this head, the scene's head
  // must run it too (its field, spin and locator are the scene's).
  const double tau = value_of(fit, cal::parameter_index(k, cal::head_parameter::tau_ms));
  const double threshold = value_of(fit, cal::parameter_index(k, cal::head_parameter::threshold));
  if (why.empty() && !std::isnan(tau) && !model.runs_physics(k))
    why = "the fit modelled its sensor physics (MODEL §12: h" + std::to_string(k + 1) +
          ".tau-ms), the scene's head runs none: give it the physics keys it was fitted with "
          "(spin-hz=, fov=, locator=, ...)";
  return {{{x, y, dgamma}, tau, threshold}, in, out};
}

}  // namespace

fit_correction::fit_correction(std::unique_ptr<state> s) : state_(std::move(s)) {}
fit_correction::~fit_correction() = default;

conescan::checked<std::unique_ptr<fit_correction>> fit_correction::of(const loaded_scene& loaded,
                                                                      const std::string& fit_path) {
  const scene_config& scene = loaded.config;
  conescan::checked<cal::fit_result> read =
      text::naming_input("apply", fit_path, [&] { return cal::read_fit_json_file(fit_path); });
  if (!read.ok()) return std::move(read).error();
  const cal::fit_result& fit = read.value();
  const std::size_t heads = scene.heads.size();
  const auto refuse = [&](const std::string& what) {
    return conescan::diagnostic{"apply", what, conescan::origin::file_line(fit_path, 0)};
  };
  if (fit.uncertainty.parameters.size() != cal::parameter_count(heads))
    return refuse("the fit has " +
                  std::to_string((fit.uncertainty.parameters.size() - cal::earth_parameter_count) /
                                 cal::head_parameter_count) +
                  " heads, the scene " + std::to_string(heads));
  for (checked<void> e : {check_coordinates(fit), check_domain(loaded, fit)})
    if (!e.ok()) {
      e.error().where = conescan::origin::file_line(fit_path, 0);
      return std::move(e).error();
    }
  const std::uint64_t rows = row_count(loaded);
  if (rows * heads > cal::max_telemetry_measurements)
    return refuse("a correction holds every row's geometry: at most " +
                  std::to_string(cal::max_telemetry_measurements) +
                  " rows x heads (shorten --duration-s or raise --step-s)");
  std::vector<double> times(rows);
  for (std::uint64_t k = 0; k < rows; ++k) times[k] = static_cast<double>(k) * scene.step_s;
  conescan::checked<cal::scene_model> model = cal::scene_model::of(loaded, times);
  if (!model.ok()) {
    conescan::diagnostic e = std::move(model).error();
    return refuse("the scene: " + e.text());
  }
  auto s = std::make_unique<state>(state{std::move(model).value(), {}, {}});
  for (std::size_t k = 0; k < heads; ++k) {
    std::string why;
    s->fitted.push_back(fitted_head_of(fit, k, s->model, why));
    if (!why.empty()) return refuse("head " + std::to_string(k + 1) + ": " + why);
  }
  double earth[cal::earth_parameter_count];
  const cal::parameter_set scene_values = cal::scene_parameters(scene);
  for (std::size_t i = 0; i < cal::earth_parameter_count; ++i) {
    const std::size_t index = cal::parameter_count(heads) - cal::earth_parameter_count + i;
    earth[i] = value_of(fit, index);
    // An undetermined horizon or limb term (or a limb the fit did not model): the scene's own
    // value predicts as well as any.
    if (!std::isfinite(earth[i])) earth[i] = scene_values.values[index];
  }
  s->earth = {earth[0], earth[1], earth[2], earth[3], earth[4]};
  return std::unique_ptr<fit_correction>(new fit_correction(std::move(s)));
}

crossings<double> fit_correction::corrected(std::uint64_t k, double t_s, std::size_t head,
                                            const crossings<double>& measured) const noexcept {
  // The core's rule (conescan/head_calibration.hpp), which flight code runs on board.
  const cal::telemetry_sample sample{static_cast<std::size_t>(k), t_s, head};
  const fitted_head& f = state_->fitted[head];
  return state_->model.corrected(sample, f.head, f.bias_in_deg, f.bias_out_deg, state_->earth,
                                 measured);
}

}  // namespace conescan::scene
