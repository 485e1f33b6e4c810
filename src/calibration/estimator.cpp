#include "calibration/estimator.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "calibration/layout.hpp"
#include "calibration/passes.hpp"
#include "calibration/report.hpp"
#include "calibration/solver.hpp"
#include "text/number_text.hpp"

namespace conescan::calibration {

measurement_sigma measurement_sigma_of(const head_noise& noise) {
  const double n2 = noise.crossing_deg * noise.crossing_deg;
  const double rounding = noise.lsb_deg * noise.lsb_deg / 12;
  return {std::sqrt(2 * n2 + rounding), std::sqrt(n2 / 2 + rounding)};
}

namespace {

/// Wall-clock seconds since construction.
class seconds_since {
 public:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// The weights of every head: from the stated noise, or a 1 deg crossing noise when no head
/// states any (see estimator.hpp). Errors: negative or non-finite noise, heads with and without.
checked<std::vector<measurement_sigma>> head_sigmas(const std::vector<head_noise>& noise,
                                                    bool noise_required, bool& unit_weights) {
  std::size_t stated = 0;
  for (std::size_t k = 0; k < noise.size(); ++k) {
    const head_noise& n = noise[k];
    if (!(std::isfinite(n.crossing_deg) && n.crossing_deg >= 0 && std::isfinite(n.lsb_deg) &&
          n.lsb_deg >= 0))
      return diagnostic{"head", "head " + std::to_string(k + 1) +
                                    ": the crossing noise and the telemetry step must be finite "
                                    "and >= 0 deg"};
    if (n.crossing_deg > 0 || n.lsb_deg > 0) ++stated;
  }
  unit_weights = stated == 0;
  if (stated != 0 && stated != noise.size())
    return diagnostic{"head", std::to_string(stated) + " of " + std::to_string(noise.size()) +
                                  " heads state a crossing noise (noise or lsb): state one for "
                                  "every head, or for none (then every head is weighted alike)"};
  if (unit_weights && noise_required)
    return diagnostic{"head",
                      "experiment design needs each head's crossing noise (noise=, in "
                      "deg): no head states one"};
  std::vector<measurement_sigma> sigmas;
  for (const head_noise& n : noise)
    sigmas.push_back(unit_weights ? measurement_sigma_of({1.0, 0.0}) : measurement_sigma_of(n));
  return sigmas;
}

checked<std::vector<measurement_sigma>> checked_setup(const fit_problem& problem,
                                                      bool& unit_weights) {
  if (!problem.parameters.any_free())
    return diagnostic{"free", "no free parameter: name at least one"};
  if (problem.noise.size() != problem.parameters.head_count)
    return diagnostic{"head", "the noise of " + std::to_string(problem.noise.size()) +
                                  " heads given for " +
                                  std::to_string(problem.parameters.head_count) + " heads"};
  for (const observation& o : problem.observations)
    if (o.sample.head >= problem.parameters.head_count || !std::isfinite(o.chord_deg) ||
        !std::isfinite(o.phase_deg))
      return diagnostic{
          "telemetry", "the measurement at t_s = " + text::shortest_text(o.sample.t_s) + " (head " +
                           std::to_string(o.sample.head + 1) +
                           ") is not a finite chord and phase of a scene head"};
  const parameter_set& p = problem.parameters;
  for (std::size_t k = 0; k < p.head_count; ++k) {
    const std::size_t sigma = parameter_index(k, head_parameter::sigma);
    const std::size_t phase = parameter_index(k, head_parameter::phase);
    if (p.free[sigma] && p.free[phase] && p.segment_s[sigma] != p.segment_s[phase])
      return diagnostic{"free", "h" + std::to_string(k + 1) + ".sigma and h" +
                                    std::to_string(k + 1) +
                                    ".phase are estimated together: they drift together or not"};
  }
  return head_sigmas(problem.noise, false, unit_weights);
}

/// The noise rounds of a fit (estimator.hpp): at most this many fits change the weights, until
/// no head's weight ratio moves by more than noise_ratio_tolerance.
constexpr int max_noise_rounds = 4;
constexpr double noise_ratio_tolerance = 0.02;
constexpr std::size_t noise_minimum_measurements = 20;
constexpr double noise_ratio_floor = 1e-6;
constexpr double normal_quartile = 0.6744897501960817;  // the normal law's 3/4 quantile
constexpr double dropped_warning_fraction = 0.01;

/// The most coordinates a fit estimates (a drifting parameter's segments included): the normal
/// equations are dense, p x p, solved and decomposed in O(p^3).
constexpr std::size_t max_coordinates = 1000;

/// A count of values as a message says it: its digits, or "over 10^15" (a segment of 1e-300 s
/// gives more than a double holds: "inf", or 2.16e+304).
std::string count_text(double count) {
  return count <= 1e15 ? std::to_string(static_cast<std::uint64_t>(count)) : "over 10^15";
}

/// The layout of the estimated values over [t_first_s, t_last_s], refused before it is built
/// where it would hold more than max_coordinates (counted in double: a segment of 1e-20 s over a
/// day is 8.6e24 segments, which neither fits a size_t nor memory).
checked<estimation_layout> bounded_layout(const parameter_set& parameters, double t_first_s,
                                          double t_last_s) {
  double total = 0;
  std::string drifting;
  for (std::size_t slot = 0; slot < parameters.free.size(); ++slot) {
    if (!parameters.free[slot]) continue;
    const double seconds = slot < parameters.segment_s.size() ? parameters.segment_s[slot] : 0.0;
    const double segments =
        seconds > 0 ? estimation_layout::segment_count(t_first_s, t_last_s, seconds) : 1;
    total += segments;
    if (seconds > 0)
      drifting += (drifting.empty() ? "" : ", ") + parameter_name(slot, parameters.head_count) +
                  "@" + text::shortest_text(seconds) + " (" + count_text(segments) + " segments)";
  }
  if (!(total <= static_cast<double>(max_coordinates)))
    return diagnostic{"free", count_text(total) + " estimated values are more than a fit takes (" +
                                  std::to_string(max_coordinates) + "): " + drifting +
                                  ": give longer segments"};
  return estimation_layout::of(parameters, t_first_s, t_last_s);
}

/// The first and last time of the measurements.
std::pair<double, double> time_span(std::span<const observation> observations) {
  if (observations.empty()) return {0.0, 0.0};
  double first = observations.front().sample.t_s, last = first;
  for (const observation& o : observations) {
    first = std::min(first, o.sample.t_s);
    last = std::max(last, o.sample.t_s);
  }
  return {first, last};
}

/// The weight ratio the scaling adopts for each head from its estimated ratio: 1 (the declared
/// noise) where none was estimated or the data are noise-free.
std::vector<double> adopted_ratios(const std::vector<double>& estimated, noise_scaling scaling) {
  std::vector<double> adopted;
  for (double r : estimated) {
    if (scaling == noise_scaling::declared || !(r >= noise_ratio_floor) || !std::isfinite(r))
      adopted.push_back(1.0);
    else
      adopted.push_back(scaling == noise_scaling::larger ? std::max(1.0, r) : r);
  }
  return adopted;
}

bool moved(const std::vector<double>& next, const std::vector<double>& current) {
  for (std::size_t k = 0; k < next.size(); ++k)
    if (std::abs(next[k] / current[k] - 1) > noise_ratio_tolerance) return true;
  return false;
}

void report_noise(const std::vector<head_noise>& stated, bool unit_weights,
                  const std::vector<double>& ratios, const std::vector<double>& weight_ratios,
                  const fit_options& options, fit_result& result) {
  const warning_limits& limits = options.limits;
  for (std::size_t k = 0; k < stated.size(); ++k) {
    head_noise_estimate n;
    n.declared_deg = stated[k].crossing_deg;
    n.ratio = ratios[k];
    // Without stated noise the ratio is in units of the 1 deg crossing noise of the weights.
    const double base_deg = unit_weights ? 1.0 : n.declared_deg;
    n.estimated_deg = base_deg > 0 ? n.ratio * base_deg : std::numeric_limits<double>::quiet_NaN();
    n.weight_ratio = weight_ratios[k];
    result.noise.push_back(n);
    if (unit_weights || !(n.ratio > limits.noise_ratio || n.ratio < 1 / limits.noise_ratio))
      continue;
    const std::string head = "h" + std::to_string(k + 1);
    std::string w =
        head + ": its residuals show " + short_number(n.ratio, 3) + " times the declared noise";
    if (n.declared_deg > 0)
      w += " (a crossing noise of " + short_number(n.estimated_deg, 3) + " deg, declared " +
           short_number(n.declared_deg) + " deg)";
    w += n.weight_ratio == 1 ? ": its weights use the declared noise"
                             : ": its weights and the 1 sigma use the estimate";
    result.warnings.push_back(w);
  }
  if (!(result.chi2_dof >= limits.chi2_dof_low && result.chi2_dof <= limits.chi2_dof_high))
    result.warnings.push_back(
        "chi2/dof " + short_number(result.chi2_dof, 3) + " is outside [" +
        text::shortest_text(limits.chi2_dof_low) + ", " +
        text::shortest_text(limits.chi2_dof_high) +
        "]: the residuals are not those of Gaussian noise at the weights used (many outliers, or "
        "a model that does not describe the data)");
}

double two_sided_binomial(std::size_t n, std::size_t k) {
  const double log_half_n = static_cast<double>(n) * std::log(0.5);
  const double log_n_factorial = std::lgamma(static_cast<double>(n) + 1);
  double tail = 0;
  for (std::size_t j = k; j <= n; ++j)
    tail += std::exp(log_n_factorial - std::lgamma(static_cast<double>(j) + 1) -
                     std::lgamma(static_cast<double>(n - j) + 1) + log_half_n);
  return std::min(1.0, 2 * tail);
}

/// Per head and residual, the outliers' signs: an effect when one sign is improbably common.
std::vector<systematic_effect> systematic_effects(const passes::outlier_scan& scan) {
  std::vector<systematic_effect> effects;
  for (std::size_t k = 0; k < scan.chord.size(); ++k)
    for (bool phase : {false, true}) {
      const passes::outlier_scan::signs& t = phase ? scan.phase[k] : scan.chord[k];
      if (t.n == 0) continue;
      const std::size_t same = std::max(t.positive, t.n - t.positive);
      const double p = two_sided_binomial(t.n, same);
      if (p < systematic_probability)
        effects.push_back({k, phase, t.n, same, t.positive * 2 > t.n ? 1 : -1,
                           t.sum_deg / static_cast<double>(t.n), p});
    }
  return effects;
}

/// What a fit carries from round to round (estimator.hpp).
struct fit_rounds {
  const estimation_layout& layout;
  passes::setup setup;  ///< its sigma: the declared times the weight ratios
  std::vector<measurement_sigma> declared;
  passes::inclusion fitted;
  Eigen::VectorXd x;
  std::vector<double> weight_ratios;  ///< per head
  std::vector<double> ratios;         ///< per head, estimated at the last solution
  passes::normal_equations at_x;      ///< at the last solution
  bool unit_weights = false;

  /// Each head's estimated noise over its declared, at x.
  std::vector<double> estimated_ratios() const {
    std::vector<double> r =
        passes::median_abs_residual(setup, fitted, x, declared, noise_minimum_measurements);
    for (double& v : r) v /= normal_quartile;
    return r;
  }
  void reweight(const fit_options& options) {
    weight_ratios = adopted_ratios(ratios, options.scaling);
    for (std::size_t k = 0; k < declared.size(); ++k)
      setup.sigma[k] = {declared[k].chord_deg * weight_ratios[k],
                        declared[k].phase_deg * weight_ratios[k]};
    // Without stated noise the loss takes its scale from the estimate, once every head has one.
    const bool robust = options.loss == robust_loss::huber &&
                        (!unit_weights || std::none_of(weight_ratios.begin(), weight_ratios.end(),
                                                       [](double r) { return r == 1.0; }));
    setup.huber_scale = robust ? options.huber_scale : 0.0;
  }
  std::vector<double> coordinates() const {
    return std::vector<double>(x.data(), x.data() + x.size());
  }
  std::vector<double> slots() const {
    return slots_with_coordinates(layout, setup.slots, coordinates());
  }
};

unconverged_fit unconverged(const fit_problem& problem, const fit_rounds& f, int iterations,
                            double cost, std::string message) {
  parameter_set last = problem.parameters;
  last.values = parameters_from_slots(f.layout, f.slots());
  return {last, iterations, cost, std::move(message), {}};
}

/// The rounds of a fit (estimator.hpp): solve, estimate the noise, re-admit, until neither
/// changes. Returns the unconverged state when a round stops without converging.
std::optional<unconverged_fit> run_rounds(fit_rounds& f, const fit_problem& problem,
                                          const fit_options& options, fit_result& result) {
  // Rounds that only set the next round's noise stop near the minimum (rough_tolerance: a fit
  // with the noise declared 10 times too small is least absolute values at first, which
  // Gauss-Newton approaches slowly); the last is taken to final_tolerance.
  double tolerance = rough_tolerance;
  for (int round = 0;; ++round) {
    solve_outcome solved =
        levenberg_marquardt(f.setup, f.fitted, f.x, options.max_iterations, tolerance);
    result.iterations += solved.iterations;
    result.solver_message = solved.message;
    result.timing.linearizations += solved.linearizations;
    result.timing.linear_solver_s += solved.linear_solver_s;
    f.x = std::move(solved.x);
    f.at_x = std::move(solved.at_x);
    if (!solved.converged)
      return unconverged(problem, f, result.iterations, f.at_x.cost, solved.message);
    f.ratios = f.estimated_ratios();
    const bool reweight = round + 1 < max_noise_rounds &&
                          moved(adopted_ratios(f.ratios, options.scaling), f.weight_ratios);
    if (reweight) f.reweight(options);
    const std::size_t back = passes::readmit(f.setup, f.fitted, f.x);
    result.timing.value_passes += 2;
    result.readmitted += back;
    if (!reweight && back == 0) {
      if (tolerance == final_tolerance) return std::nullopt;
      tolerance = final_tolerance;
    }
  }
}

/// Per head the measurements left out at the solution, with a warning above 1 % of a head's.
void report_dropped(const fit_rounds& f, const fit_problem& problem, fit_result& result) {
  result.dropped_per_head.assign(f.layout.head_count, 0);
  for (std::size_t i = 0; i < f.fitted.size(); ++i)
    if (f.fitted[i] == 0) ++result.dropped_per_head[problem.observations[i].sample.head];
  for (std::size_t k = 0; k < f.layout.head_count; ++k) {
    const std::size_t out = result.dropped_per_head[k];
    const double all = static_cast<double>(out + result.observations_per_head[k]);
    if (out == 0 || !(static_cast<double>(out) > dropped_warning_fraction * all)) continue;
    result.warnings.push_back("h" + std::to_string(k + 1) + ": " + std::to_string(out) +
                              " of its " + std::to_string(out + result.observations_per_head[k]) +
                              " measurements (" +
                              short_number(100 * static_cast<double>(out) / all, 3) +
                              " %) cannot be predicted at the solution and are left out");
  }
}

/// The warnings about outliers that share a sign.
void report_systematic(fit_result& result) {
  for (const systematic_effect& e : result.systematic)
    result.warnings.push_back(
        "h" + std::to_string(e.head + 1) + ": " + std::to_string(e.same_sign) + " of its " +
        std::to_string(e.outliers) + " outliers have a " + (e.sign > 0 ? "positive" : "negative") +
        (e.phase ? " phase" : " chord") + " residual (mean " +
        short_number(e.mean_residual_deg, 3) +
        " deg): a systematic effect the model does not describe, not noise");
}

/// Residual RMS per head (deg), the outliers and the systematic effects.
void summarise_residuals(const fit_rounds& f, const fit_options& options, fit_result& result) {
  const passes::normal_equations& n = f.at_x;
  result.observations_per_head = n.count;
  for (std::size_t k = 0; k < n.count.size(); ++k)
    result.residual_rms_deg.push_back(
        n.count[k] == 0
            ? std::numeric_limits<double>::quiet_NaN()
            : std::sqrt(n.sum_squares_deg2[k] / (2.0 * static_cast<double>(n.count[k]))));
  const passes::outlier_scan scan = passes::find_outliers(
      f.setup, f.fitted, f.x, result.chi2_dof, options.outlier_threshold, options.outliers_listed);
  result.timing.value_passes += 1;
  result.outlier_count = scan.count;
  result.worst_outliers = scan.worst;
  result.systematic = systematic_effects(scan);
}

/// The fitted measurements in each segment of each drifting parameter.
void count_segments(const fit_rounds& f, const fit_problem& problem, uncertainty_report& u) {
  for (drift_history& h : u.drift)
    for (std::size_t i = 0; i < f.fitted.size(); ++i)
      if (f.fitted[i] != 0)
        ++h.segments[f.layout.segment_of(h.parameter, problem.observations[i].sample.t_s)]
              .observations;
}

/// The converged fit's statistics, uncertainty and report from the last round.
void summarise_fit(const fit_rounds& f, const fit_problem& problem, const fit_options& options,
                   fit_result& result) {
  const passes::normal_equations& n = f.at_x;
  std::size_t fitted = 0;
  for (std::size_t c : n.count) fitted += c;
  result.residual_count = 2 * fitted;
  const std::vector<double> x = f.coordinates();
  const std::size_t rank = analyse_uncertainty(f.layout, f.setup.slots, x, n.h, 1.0).rank;
  result.dof = result.residual_count - rank;
  result.chi2_dof = n.chi2 / static_cast<double>(result.dof);
  result.uncertainty = analyse_uncertainty(f.layout, f.setup.slots, x, n.h, result.chi2_dof);
  count_segments(f, problem, result.uncertainty);
  result.loss = f.setup.huber_scale > 0 ? robust_loss::huber : robust_loss::none;
  result.huber_scale = f.setup.huber_scale;
  result.unit_weights = f.unit_weights;
  result.outlier_threshold = options.outlier_threshold;
  result.scaling = options.scaling;
  summarise_residuals(f, options, result);
  report_noise(problem.noise, f.unit_weights, f.ratios, f.weight_ratios, options, result);
  report_dropped(f, problem, result);
  report_systematic(result);
}

}  // namespace

const char* noise_scaling_name(noise_scaling scaling) noexcept {
  switch (scaling) {
    case noise_scaling::estimated:
      return "estimated";
    case noise_scaling::larger:
      return "larger";
    case noise_scaling::declared:
      return "declared";
  }
  return "declared";
}

checked<fit_outcome> fit(const fit_problem& problem, const fit_options& options) {
  const seconds_since setup_start;
  bool unit_weights = false;
  checked<std::vector<measurement_sigma>> sigmas = checked_setup(problem, unit_weights);
  if (!sigmas.ok()) return sigmas.error();
  const auto [t_first_s, t_last_s] = time_span(problem.observations);
  checked<estimation_layout> bounded = bounded_layout(problem.parameters, t_first_s, t_last_s);
  if (!bounded.ok()) return bounded.error();
  const estimation_layout& layout = bounded.value();
  const std::vector<double> start = slots_from_parameters(layout, problem.parameters);
  const std::vector<double> coordinates = coordinates_from_slots(layout, start);
  // Without stated noise the loss has no scale until the noise is estimated (estimator.hpp).
  const bool robust = options.loss == robust_loss::huber && !unit_weights;
  fit_rounds f{layout,
               {problem.model, problem.observations, &layout, start, sigmas.value(),
                robust ? options.huber_scale : 0.0, options.threads},
               sigmas.value(),
               passes::inclusion(problem.observations.size(), 0),
               Eigen::Map<const Eigen::VectorXd>(coordinates.data(),
                                                 static_cast<Eigen::Index>(coordinates.size())),
               std::vector<double>(layout.head_count, 1.0),
               {},
               {},
               unit_weights};
  fit_result result;
  const std::size_t predicted = passes::readmit(f.setup, f.fitted, f.x);
  result.dropped_at_start = problem.observations.size() - predicted;
  if (predicted == 0)
    return diagnostic{"telemetry", "no measurement that the model can predict at the start (" +
                                       std::to_string(result.dropped_at_start) + " dropped)"};
  if (2 * predicted <= layout.coordinates.size())
    return diagnostic{"free", std::to_string(2 * predicted) + " residuals cannot determine " +
                                  std::to_string(layout.coordinates.size()) + " free parameters"};
  result.timing.value_passes = 1;
  result.timing.setup_s = setup_start.elapsed();
  const seconds_since solve_start;
  std::optional<unconverged_fit> stopped = run_rounds(f, problem, options, result);
  if (stopped) return fit_outcome(std::in_place_type<unconverged_fit>, std::move(*stopped));
  result.timing.solve_s = solve_start.elapsed();
  const seconds_since uncertainty_start;
  summarise_fit(f, problem, options, result);
  result.timing.uncertainty_s = uncertainty_start.elapsed();
  if (options.each_residual)
    passes::for_each_residual(f.setup, f.fitted, f.x, result.chi2_dof, options.each_residual);
  return fit_outcome(std::in_place_type<fit_result>, std::move(result));
}

checked<design_result> predict_uncertainty(const forward_model& model,
                                           const parameter_set& parameters,
                                           const std::vector<telemetry_sample>& samples,
                                           const std::vector<head_noise>& noise, int threads) {
  if (!parameters.any_free()) return diagnostic{"free", "no free parameter: name at least one"};
  if (noise.size() != parameters.head_count)
    return diagnostic{"head", "the noise of " + std::to_string(noise.size()) + " heads given for " +
                                  std::to_string(parameters.head_count) + " heads"};
  bool unit_weights = false;
  checked<std::vector<measurement_sigma>> sigmas = head_sigmas(noise, true, unit_weights);
  if (!sigmas.ok()) return sigmas.error();
  std::vector<observation> planned;
  planned.reserve(samples.size());
  for (const telemetry_sample& s : samples) {
    if (s.head >= parameters.head_count)
      return diagnostic{"head", "a planned measurement of head " + std::to_string(s.head + 1) +
                                    " in a scene of " + std::to_string(parameters.head_count) +
                                    " heads"};
    planned.push_back({s, 0.0, 0.0});
  }
  const auto [t_first_s, t_last_s] = time_span(planned);
  checked<estimation_layout> bounded = bounded_layout(parameters, t_first_s, t_last_s);
  if (!bounded.ok()) return bounded.error();
  const estimation_layout& layout = bounded.value();
  const std::vector<double> slots = slots_from_parameters(layout, parameters);
  const std::vector<double> coordinates = coordinates_from_slots(layout, slots);
  const passes::setup setup{&model, planned, &layout, slots, sigmas.value(), 0.0, threads};
  const Eigen::Map<const Eigen::VectorXd> x(coordinates.data(),
                                            static_cast<Eigen::Index>(coordinates.size()));
  passes::inclusion fitted(planned.size(), 0);
  const std::size_t predicted = passes::readmit(setup, fitted, x);
  design_result result;
  result.dropped = planned.size() - predicted;
  result.residual_count = 2 * predicted;
  const passes::normal_equations n = passes::linearize(setup, fitted, x);
  result.uncertainty = analyse_uncertainty(layout, slots, coordinates, n.h, 1.0);
  return result;
}

}  // namespace conescan::calibration
