#include "calibration/estimator.hpp"

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include "calibration/layout.hpp"
#include "calibration/report.hpp"
#include "text/number_text.hpp"

namespace conescan::calibration {

measurement_sigma measurement_sigma_of(const head_noise& noise) {
  const double n2 = noise.crossing_deg * noise.crossing_deg;
  const double rounding = noise.lsb_deg * noise.lsb_deg / 12;
  return {std::sqrt(2 * n2 + rounding), std::sqrt(n2 / 2 + rounding)};
}

namespace {

constexpr std::size_t bias_in_offset = static_cast<std::size_t>(head_parameter::bias_in);
constexpr std::size_t bias_out_offset = static_cast<std::size_t>(head_parameter::bias_out);
constexpr int head_block_size = static_cast<int>(head_parameter_count);
constexpr int earth_block_size = static_cast<int>(earth_parameter_count);

/// The two whitened residuals of one observation, for any scalar the model accepts.
class observation_residual {
 public:
  observation_residual(const forward_model* model, const observation& measured,
                       misalignment_form form, measurement_sigma sigma)
      : model_(model), measured_(measured), form_(form), sigma_(sigma) {}

  template <class T>
  bool operator()(const T* head, const T* earth, T* residual) const {
    using std::isfinite;
    const predicted_measurement<T> p =
        model_->predict(measured_.sample, head_geometry_of(head, form_), earth_geometry_of(earth));
    if (p.state != status::ok) return false;
    const predicted_measurement<T> biased =
        with_crossing_biases(p, head[bias_in_offset], head[bias_out_offset]);
    residual[0] = (measured_.chord_deg - biased.chord_deg) / sigma_.chord_deg;
    residual[1] =
        wrapped_difference_deg(T(measured_.phase_deg - biased.phase_deg)) / sigma_.phase_deg;
    return isfinite(residual[0]) && isfinite(residual[1]);
  }

  const observation& measured() const noexcept { return measured_; }
  const measurement_sigma& sigma() const noexcept { return sigma_; }
  observation_residual with_sigma(measurement_sigma sigma) const {
    return {model_, measured_, form_, sigma};
  }

 private:
  const forward_model* model_;
  observation measured_;
  misalignment_form form_;
  measurement_sigma sigma_;
};

using residual_cost =
    ceres::AutoDiffCostFunction<observation_residual, 2, head_block_size, earth_block_size>;

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

/// Runs fn(begin, end, part) over `threads` contiguous parts of [0, n).
template <class Fn>
void parallel_parts(std::size_t n, int threads, Fn fn) {
  const std::size_t parts = std::clamp<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)),
                                                    1, std::max<std::size_t>(n, 1));
  std::vector<std::thread> workers;
  for (std::size_t part = 1; part < parts; ++part)
    workers.emplace_back(fn, n * part / parts, n * (part + 1) / parts, part);
  fn(std::size_t{0}, n / parts, std::size_t{0});
  for (std::thread& w : workers) w.join();
}

/// One observation at the solution: whitened residuals' squared norm s, robust weight, and the
/// residuals in deg.
struct evaluated {
  double s = 0;
  double weight = 1;
  double chord_deg = 0;
  double phase_deg = 0;
};

/// The information sum w J^T J over the layout's coordinates, and every observation evaluated,
/// at the slot values (Jets through the same residual functor as the fit).
struct information_pass {
  Eigen::MatrixXd information;
  std::vector<evaluated> rows;
  bool ok = true;
};

information_pass evaluate_information(const std::vector<observation_residual>& residuals,
                                      const estimation_layout& layout,
                                      const std::vector<double>& slots,
                                      const ceres::LossFunction* loss, int threads) {
  const auto p = static_cast<Eigen::Index>(layout.coordinates.size());
  std::vector<int> coordinate_of(slots.size(), -1);
  for (std::size_t i = 0; i < layout.coordinates.size(); ++i)
    coordinate_of[layout.coordinates[i]] = static_cast<int>(i);
  information_pass pass{Eigen::MatrixXd::Zero(p, p), std::vector<evaluated>(residuals.size()),
                        true};
  std::vector<Eigen::MatrixXd> partial(static_cast<std::size_t>(std::max(threads, 1)),
                                       Eigen::MatrixXd::Zero(p, p));
  std::vector<char> part_ok(partial.size(), 1);
  parallel_parts(
      residuals.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t part) {
        Eigen::MatrixXd& h = partial[part];
        for (std::size_t i = begin; i < end; ++i) {
          const observation_residual& r = residuals[i];
          const std::size_t head_base = estimation_layout::head_block(r.measured().sample.head);
          parameter_jet head[head_block_size], earth[earth_block_size], out[2];
          int slot_of_derivative[jet_size];
          for (int j = 0; j < head_block_size; ++j) {
            head[j] = parameter_jet(slots[head_base + static_cast<std::size_t>(j)], j);
            slot_of_derivative[j] = coordinate_of[head_base + static_cast<std::size_t>(j)];
          }
          for (int j = 0; j < earth_block_size; ++j) {
            earth[j] = parameter_jet(slots[layout.earth_block() + static_cast<std::size_t>(j)],
                                     head_block_size + j);
            slot_of_derivative[head_block_size + j] =
                coordinate_of[layout.earth_block() + static_cast<std::size_t>(j)];
          }
          if (!r(head, earth, out)) {
            part_ok[part] = 0;
            continue;
          }
          evaluated& e = pass.rows[i];
          e.s = out[0].a * out[0].a + out[1].a * out[1].a;
          if (loss != nullptr) {
            double rho[3];
            loss->Evaluate(e.s, rho);
            e.weight = rho[1];
          }
          e.chord_deg = out[0].a * r.sigma().chord_deg;
          e.phase_deg = out[1].a * r.sigma().phase_deg;
          for (int a = 0; a < jet_size; ++a) {
            if (slot_of_derivative[a] < 0) continue;
            for (int b = 0; b < jet_size; ++b) {
              if (slot_of_derivative[b] < 0) continue;
              h(slot_of_derivative[a], slot_of_derivative[b]) +=
                  e.weight * (out[0].v[a] * out[0].v[b] + out[1].v[a] * out[1].v[b]);
            }
          }
        }
      });
  for (std::size_t part = 0; part < partial.size(); ++part) {
    pass.information += partial[part];
    pass.ok = pass.ok && part_ok[part] != 0;
  }
  return pass;
}

/// The residual functors of the observations the model predicts at `slots`; `dropped` lists
/// the others (indices into `observations`).
std::vector<observation_residual> predictable(const forward_model* model,
                                              const std::vector<observation>& observations,
                                              const estimation_layout& layout,
                                              const std::vector<measurement_sigma>& sigmas,
                                              const std::vector<double>& slots,
                                              std::vector<std::size_t>& dropped) {
  std::vector<observation_residual> kept;
  kept.reserve(observations.size());
  dropped.clear();
  for (std::size_t i = 0; i < observations.size(); ++i) {
    const observation& o = observations[i];
    const std::size_t k = o.sample.head;
    observation_residual r(model, o, layout.forms[k], sigmas[k]);
    double out[2];
    if (r(&slots[estimation_layout::head_block(k)], &slots[layout.earth_block()], out))
      kept.push_back(r);
    else
      dropped.push_back(i);
  }
  return kept;
}

/// The dropped observations the model predicts at `slots` join `residuals` (with each head's
/// current 1 sigma); returns how many.
std::size_t readmit(const forward_model* model, const std::vector<observation>& observations,
                    const estimation_layout& layout, const std::vector<measurement_sigma>& sigmas,
                    const std::vector<double>& slots, std::vector<std::size_t>& dropped,
                    std::vector<observation_residual>& residuals) {
  std::vector<observation> candidates;
  for (std::size_t i : dropped) candidates.push_back(observations[i]);
  std::vector<std::size_t> still;
  std::vector<observation_residual> back =
      predictable(model, candidates, layout, sigmas, slots, still);
  for (std::size_t& i : still) i = dropped[i];
  dropped = std::move(still);
  residuals.insert(residuals.end(), back.begin(), back.end());
  return back.size();
}

/// Every block Ceres sees: its held slots constant (SubsetManifold), or the whole block.
void hold_slots(ceres::Problem& problem, const estimation_layout& layout,
                std::vector<double>& slots) {
  auto hold = [&](std::size_t base, int size) {
    double* block = &slots[base];
    if (!problem.HasParameterBlock(block)) return;
    std::vector<int> held;
    for (int j = 0; j < size; ++j)
      if (!layout.free[base + static_cast<std::size_t>(j)]) held.push_back(j);
    if (held.size() == static_cast<std::size_t>(size))
      problem.SetParameterBlockConstant(block);
    else if (!held.empty())
      problem.SetManifold(block, new ceres::SubsetManifold(size, held));
  };
  for (std::size_t k = 0; k < layout.head_count; ++k)
    hold(estimation_layout::head_block(k), head_block_size);
  hold(layout.earth_block(), earth_block_size);
}

struct solve_outcome {
  bool converged = false;
  int iterations = 0;
  double cost = 0;
  std::string message;
  fit_timing timing;
};

solve_outcome solve(const std::vector<observation_residual>& residuals,
                    const estimation_layout& layout, std::vector<double>& slots,
                    ceres::LossFunction* loss, const fit_options& options) {
  const seconds_since build_start;
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (const observation_residual& r : residuals)
    problem.AddResidualBlock(new residual_cost(new observation_residual(r)), loss,
                             &slots[estimation_layout::head_block(r.measured().sample.head)],
                             &slots[layout.earth_block()]);
  hold_slots(problem, layout, slots);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.num_threads = std::max(options.threads, 1);
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.function_tolerance = 1e-12;
  solver_options.parameter_tolerance = 1e-12;
  solver_options.gradient_tolerance = 1e-12;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  fit_timing timing;
  timing.setup_s = build_start.elapsed();
  const seconds_since start;
  ceres::Solve(solver_options, &problem, &summary);
  timing.solve_s = start.elapsed();
  timing.residuals_s = summary.residual_evaluation_time_in_seconds;
  timing.jacobians_s = summary.jacobian_evaluation_time_in_seconds;
  timing.linear_solver_s = summary.linear_solver_time_in_seconds;
  timing.residual_evaluations = summary.num_residual_evaluations;
  timing.jacobian_evaluations = summary.num_jacobian_evaluations;
  return {summary.termination_type == ceres::CONVERGENCE,
          static_cast<int>(summary.iterations.size()), summary.final_cost, summary.message, timing};
}

/// The probability that a fair coin thrown n times shows one face at least k times, either face
/// (two-sided; k > n / 2), summed in logarithms so that n may be large.
double two_sided_binomial(std::size_t n, std::size_t k) {
  const double log_half_n = static_cast<double>(n) * std::log(0.5);
  const double log_n_factorial = std::lgamma(static_cast<double>(n) + 1);
  double tail = 0;
  for (std::size_t j = k; j <= n; ++j)
    tail += std::exp(log_n_factorial - std::lgamma(static_cast<double>(j) + 1) -
                     std::lgamma(static_cast<double>(n - j) + 1) + log_half_n);
  return std::min(1.0, 2 * tail);
}

/// Per head and component, the outliers' signs: an effect when one sign is improbably common.
std::vector<systematic_effect> systematic_effects(const std::vector<outlier>& outliers,
                                                  std::size_t head_count) {
  std::vector<systematic_effect> effects;
  for (std::size_t k = 0; k < head_count; ++k)
    for (bool phase : {false, true}) {
      std::size_t n = 0, positive = 0;
      double sum = 0;
      for (const outlier& o : outliers) {
        if (o.sample.head != k) continue;
        const double r = phase ? o.phase_residual_deg : o.chord_residual_deg;
        ++n;
        positive += r > 0;
        sum += r;
      }
      if (n == 0) continue;
      const std::size_t same = std::max(positive, n - positive);
      const double p = two_sided_binomial(n, same);
      if (p < systematic_probability)
        effects.push_back(
            {k, phase, n, same, positive * 2 > n ? 1 : -1, sum / static_cast<double>(n), p});
    }
  return effects;
}

/// Residual RMS per head (deg), outliers, and the robust chi-square of the evaluated rows.
void summarise_rows(const std::vector<observation_residual>& residuals,
                    const information_pass& pass, std::size_t head_count,
                    const fit_options& options, fit_result& result) {
  std::vector<double> sum_squares(head_count, 0.0);
  result.observations_per_head.assign(head_count, 0);
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const std::size_t k = residuals[i].measured().sample.head;
    const evaluated& e = pass.rows[i];
    sum_squares[k] += e.chord_deg * e.chord_deg + e.phase_deg * e.phase_deg;
    ++result.observations_per_head[k];
  }
  for (std::size_t k = 0; k < head_count; ++k)
    result.residual_rms_deg.push_back(
        result.observations_per_head[k] == 0
            ? std::numeric_limits<double>::quiet_NaN()
            : std::sqrt(sum_squares[k] /
                        (2.0 * static_cast<double>(result.observations_per_head[k]))));
  std::vector<outlier> found;
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const evaluated& e = pass.rows[i];
    const double z = std::sqrt(e.s / result.chi2_dof);
    if (z > options.outlier_threshold)
      found.push_back({residuals[i].measured().sample, e.chord_deg, e.phase_deg, z});
  }
  result.outlier_count = found.size();
  result.systematic = systematic_effects(found, head_count);
  const std::size_t listed = std::min(found.size(), options.outliers_listed);
  std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(listed), found.end(),
                    [](const outlier& a, const outlier& b) { return a.normalised > b.normalised; });
  found.resize(listed);
  result.worst_outliers = std::move(found);
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
  return head_sigmas(problem.noise, false, unit_weights);
}

/// The noise rounds of a fit (estimator.hpp): at most this many fits, each from the last one's
/// solution, until no head's weight ratio moves by more than noise_ratio_tolerance.
constexpr int max_noise_rounds = 4;
constexpr double noise_ratio_tolerance = 0.02;
constexpr std::size_t noise_minimum_measurements = 20;
constexpr double noise_ratio_floor = 1e-6;
constexpr double normal_quartile = 0.6744897501960817;  // the normal law's 3/4 quantile
constexpr double dropped_warning_fraction = 0.01;

/// Per head the robust scale of the residuals at the solution in units of `declared`: the
/// median of the absolute whitened residuals (chord and phase pooled) over normal_quartile;
/// NaN for a head with fewer than noise_minimum_measurements.
std::vector<double> noise_ratios(const std::vector<observation_residual>& residuals,
                                 const information_pass& pass,
                                 const std::vector<measurement_sigma>& declared) {
  std::vector<std::vector<double>> whitened(declared.size());
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const std::size_t k = residuals[i].measured().sample.head;
    whitened[k].push_back(std::abs(pass.rows[i].chord_deg / declared[k].chord_deg));
    whitened[k].push_back(std::abs(pass.rows[i].phase_deg / declared[k].phase_deg));
  }
  std::vector<double> ratios;
  for (std::vector<double>& z : whitened) {
    if (z.size() < 2 * noise_minimum_measurements) {
      ratios.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const auto middle = z.begin() + static_cast<std::ptrdiff_t>(z.size() / 2);
    std::nth_element(z.begin(), middle, z.end());
    double median = *middle;
    if (z.size() % 2 == 0) median = (median + *std::max_element(z.begin(), middle)) / 2;
    ratios.push_back(median / normal_quartile);
  }
  return ratios;
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

/// The residual functors with each head's declared 1 sigma times its weight ratio.
std::vector<observation_residual> reweighted(const std::vector<observation_residual>& residuals,
                                             const std::vector<measurement_sigma>& declared,
                                             const std::vector<double>& ratios) {
  std::vector<observation_residual> out;
  out.reserve(residuals.size());
  for (const observation_residual& r : residuals) {
    const std::size_t k = r.measured().sample.head;
    out.push_back(
        r.with_sigma({declared[k].chord_deg * ratios[k], declared[k].phase_deg * ratios[k]}));
  }
  return out;
}

bool moved(const std::vector<double>& next, const std::vector<double>& current) {
  for (std::size_t k = 0; k < next.size(); ++k)
    if (std::abs(next[k] / current[k] - 1) > noise_ratio_tolerance) return true;
  return false;
}

/// The noise report of each head and the warnings about the noise and chi2/dof.
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

unconverged_fit unconverged(const fit_problem& problem, const estimation_layout& layout,
                            const std::vector<double>& slots, int iterations, double cost,
                            std::string message) {
  parameter_set last = problem.parameters;
  last.values = parameters_from_slots(layout, slots);
  return {last, iterations, cost, std::move(message)};
}

/// What a fit carries from round to round (estimator.hpp): the measurements in and out, the
/// slot values, each head's weight ratio, the loss, and the last round's evaluation.
struct fit_rounds {
  const estimation_layout& layout;
  std::vector<double> slots;
  std::vector<observation_residual> residuals;
  std::vector<std::size_t> dropped;   ///< indices of the observations left out
  std::vector<double> weight_ratios;  ///< per head
  std::vector<double> ratios;         ///< per head, estimated at the last solution
  bool robust = false;
  information_pass pass;

  std::vector<measurement_sigma> sigmas(const std::vector<measurement_sigma>& declared) const {
    std::vector<measurement_sigma> out;
    for (std::size_t k = 0; k < declared.size(); ++k)
      out.push_back(
          {declared[k].chord_deg * weight_ratios[k], declared[k].phase_deg * weight_ratios[k]});
    return out;
  }
  void reweight(const std::vector<measurement_sigma>& declared, const fit_options& options,
                bool unit_weights) {
    weight_ratios = adopted_ratios(ratios, options.scaling);
    residuals = reweighted(residuals, declared, weight_ratios);
    // Without stated noise the loss takes its scale from the estimate, once every head has one.
    robust = options.loss == robust_loss::huber &&
             (!unit_weights || std::none_of(weight_ratios.begin(), weight_ratios.end(),
                                            [](double r) { return r == 1.0; }));
  }
};

void add_timing(fit_timing& total, const fit_timing& round) {
  total.setup_s += round.setup_s;
  total.solve_s += round.solve_s;
  total.residuals_s += round.residuals_s;
  total.jacobians_s += round.jacobians_s;
  total.linear_solver_s += round.linear_solver_s;
  total.residual_evaluations += round.residual_evaluations;
  total.jacobian_evaluations += round.jacobian_evaluations;
}

/// Per head the measurements left out at the solution, with a warning above 1 % of a head's.
void report_dropped(const fit_rounds& f, const std::vector<observation>& observations,
                    fit_result& result) {
  result.dropped_per_head.assign(f.layout.head_count, 0);
  for (std::size_t i : f.dropped) ++result.dropped_per_head[observations[i].sample.head];
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

/// The converged fit's statistics, uncertainty and report from the last round.
void summarise_fit(const fit_rounds& f, const fit_problem& problem, const fit_options& options,
                   bool unit_weights, fit_result& result) {
  result.residual_count = 2 * f.residuals.size();
  double chi2 = 0;
  for (const evaluated& e : f.pass.rows) chi2 += e.weight * e.weight * e.s;
  const std::size_t rank = analyse_uncertainty(f.layout, f.slots, f.pass.information, 1.0).rank;
  result.dof = result.residual_count - rank;
  result.chi2_dof = chi2 / static_cast<double>(result.dof);
  result.uncertainty = analyse_uncertainty(f.layout, f.slots, f.pass.information, result.chi2_dof);
  result.loss = f.robust ? robust_loss::huber : robust_loss::none;
  result.huber_scale = f.robust ? options.huber_scale : 0.0;
  result.unit_weights = unit_weights;
  result.outlier_threshold = options.outlier_threshold;
  result.scaling = options.scaling;
  summarise_rows(f.residuals, f.pass, f.layout.head_count, options, result);
  report_noise(problem.noise, unit_weights, f.ratios, f.weight_ratios, options, result);
  report_dropped(f, problem.observations, result);
  report_systematic(result);
}

/// The rounds of a fit (estimator.hpp): solve, estimate the noise, re-admit, until neither
/// changes. Returns the unconverged state when a round stops without converging.
std::optional<unconverged_fit> run_rounds(fit_rounds& f, const fit_problem& problem,
                                          const fit_options& options,
                                          const std::vector<measurement_sigma>& declared,
                                          bool unit_weights, fit_result& result,
                                          fit_timing& timing) {
  ceres::HuberLoss huber(options.huber_scale);
  for (int round = 0;; ++round) {
    const solve_outcome solved =
        solve(f.residuals, f.layout, f.slots, f.robust ? &huber : nullptr, options);
    result.iterations += solved.iterations;
    result.solver_message = solved.message;
    add_timing(timing, solved.timing);
    if (!solved.converged)
      return unconverged(problem, f.layout, f.slots, result.iterations, solved.cost,
                         solved.message);
    f.pass = evaluate_information(f.residuals, f.layout, f.slots, f.robust ? &huber : nullptr,
                                  options.threads);
    if (!f.pass.ok)
      return unconverged(problem, f.layout, f.slots, result.iterations, solved.cost,
                         "the model cannot predict every measurement at the solution");
    f.ratios = noise_ratios(f.residuals, f.pass, declared);
    const bool reweight = round + 1 < max_noise_rounds &&
                          moved(adopted_ratios(f.ratios, options.scaling), f.weight_ratios);
    if (reweight) f.reweight(declared, options, unit_weights);
    const std::size_t back = readmit(problem.model, problem.observations, f.layout,
                                     f.sigmas(declared), f.slots, f.dropped, f.residuals);
    result.readmitted += back;
    if (!reweight && back == 0) return std::nullopt;  // else again, from this solution
  }
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
  const std::vector<measurement_sigma>& declared = sigmas.value();
  const estimation_layout layout = estimation_layout::of(problem.parameters);
  fit_rounds f{layout, slots_from_parameters(layout, problem.parameters), {}, {}, {}, {}, false,
               {}};
  fit_result result;
  f.residuals =
      predictable(problem.model, problem.observations, layout, declared, f.slots, f.dropped);
  result.dropped_at_start = f.dropped.size();
  if (f.residuals.empty())
    return diagnostic{"telemetry", "no measurement that the model can predict at the start (" +
                                       std::to_string(result.dropped_at_start) + " dropped)"};
  if (2 * f.residuals.size() <= layout.coordinates.size())
    return diagnostic{"free", std::to_string(2 * f.residuals.size()) +
                                  " residuals cannot determine " +
                                  std::to_string(layout.coordinates.size()) + " free parameters"};
  // Without stated noise the loss has no scale until the noise is estimated (estimator.hpp).
  f.robust = options.loss == robust_loss::huber && !unit_weights;
  f.weight_ratios.assign(layout.head_count, 1.0);
  fit_timing timing;
  timing.setup_s = setup_start.elapsed();
  std::optional<unconverged_fit> stopped =
      run_rounds(f, problem, options, declared, unit_weights, result, timing);
  if (stopped) return fit_outcome(std::in_place_type<unconverged_fit>, std::move(*stopped));
  const seconds_since uncertainty_start;
  summarise_fit(f, problem, options, unit_weights, result);
  result.timing = timing;
  result.timing.uncertainty_s = uncertainty_start.elapsed();
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
  const estimation_layout layout = estimation_layout::of(parameters);
  const std::vector<double> slots = slots_from_parameters(layout, parameters);
  design_result result;
  std::vector<std::size_t> dropped;
  const std::vector<observation_residual> residuals =
      predictable(&model, planned, layout, sigmas.value(), slots, dropped);
  result.dropped = dropped.size();
  result.residual_count = 2 * residuals.size();
  const information_pass pass = evaluate_information(residuals, layout, slots, nullptr, threads);
  result.uncertainty = analyse_uncertainty(layout, slots, pass.information, 1.0);
  return result;
}

}  // namespace conescan::calibration
