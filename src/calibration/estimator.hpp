// The estimator of MODEL §11: fit() minimises the telemetry's chord and phase residuals (measured
// minus predicted, over their 1 sigma) under a robust loss, by Levenberg-Marquardt on normal
// equations streamed from the data (solver.hpp, passes.hpp: a fit holds its telemetry and little
// more), Jacobians by automatic differentiation (ceres::Jet through the model), then reports the
// uncertainty and observability of uncertainty.hpp. predict_uncertainty() is experiment design:
// the same analysis from the Fisher information alone.
//
// The rules (docs/CALIBRATION.md, "The estimator" to "Uncertainty and observability", gives the
// reasons and the measurements):
//  - weights: a crossing noise n gives the chord sqrt(2) n and the phase n / sqrt(2),
//    uncorrelated; a telemetry step lsb adds lsb^2 / 12 to each variance. Without stated noise
//    (n = lsb = 0 on every head): a 1 deg crossing noise, the robust loss off until the noise is
//    estimated; heads with and without noise in one fit: refused;
//  - Huber's loss on each measurement's whitened pair, s = r_chord^2 + r_phase^2, at a = 3;
//  - each head's noise estimated from its residuals (their median absolute value over 0.674490),
//    its weights scaled by it and the fit run again until no ratio moves by more than 2 % (at most
//    4 fits; a head of fewer than 20 measurements keeps its declared weights);
//  - measurements the model cannot predict at the start are tested again at each solution and
//    rejoin when predictable; those still out are counted (a warning above 1 % of a head's);
//  - outliers: a normalised residual sqrt(s / (chi2/dof)) beyond 6, counted, the worst listed;
//    a head's outliers sharing a sign beyond a binomial probability of 1e-3: a systematic effect;
//  - the 1 sigma: the information sum w J^T J (w = rho'(s), Huber's weight) inverted and scaled by
//    chi2/dof = sum w^2 s / (residuals - rank): MODEL §11's (J^T W J)^-1 chi2/dof without the loss.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "calibration/forward_model.hpp"
#include "calibration/parameters.hpp"
#include "calibration/uncertainty.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

/// A head's stated measurement noise (deg), as the scene's noise and lsb of the head.
struct head_noise {
  double crossing_deg = 0;  ///< 1 sigma of each crossing azimuth
  double lsb_deg = 0;       ///< telemetry step of the chord and the phase
};

/// 1 sigma of a head's chord and phase (deg) from its noise (see the top of this file).
struct measurement_sigma {
  double chord_deg;
  double phase_deg;
};
measurement_sigma measurement_sigma_of(const head_noise& noise);

enum class robust_loss : unsigned char { none, huber };

/// How a fit weights each head (see the top of this file).
enum class noise_scaling : unsigned char {
  estimated,  ///< the declared 1 sigma times the ratio estimated from the head's residuals
  larger,     ///< the larger of the declared and the estimated noise
  declared,   ///< the declared noise alone (the 1 sigma still scaled by chi2/dof)
};

/// The word of a noise scaling ("estimated", "larger", "declared").
const char* noise_scaling_name(noise_scaling scaling) noexcept;

/// What a fit warns about: a head whose estimated noise is more than `noise_ratio` times its
/// declared noise or less than 1 / noise_ratio times it (at 1.5 the variance is off by 2.25:
/// with 20 measurements, the fewest a ratio is estimated from, the ratio's own scatter is about
/// 18 %, so 1.5 is 2.8 of its standard deviations), and a chi2/dof outside [low, high] (with
/// the noise estimated chi2/dof is near 1 by construction; far from it the residuals are not
/// those of Gaussian noise: many outliers, or a model that does not describe the data).
struct warning_limits {
  double noise_ratio = 1.5;
  double chi2_dof_low = 0.5;
  double chi2_dof_high = 2;
};

/// One measurement's residuals at a converged fit's solution (deg), as a residuals file writes
/// them.
struct residual_row {
  const observation* measured = nullptr;
  bool fitted = false;     ///< false: left out (the model cannot predict it at the solution)
  bool predicted = false;  ///< false: no residuals (NaN)
  double chord_deg = 0;    ///< measured minus predicted
  double phase_deg = 0;    ///< measured minus predicted, in [-180, 180]
  double normalised = 0;   ///< sqrt(s / (chi2/dof)), s in units of the weights' 1 sigma
};

/// The fit's settings (the program validates them: scales and threshold > 0, threads and
/// iterations >= 1).
struct fit_options {
  robust_loss loss = robust_loss::huber;
  double huber_scale = 3;        ///< a, in units of the stated noise
  double outlier_threshold = 6;  ///< normalised residual beyond which an observation is listed
  std::size_t outliers_listed = 10;
  int max_iterations = 100;
  int threads = 2;  ///< threads of every pass over the data
  noise_scaling scaling = noise_scaling::estimated;
  warning_limits limits;
  /// When set, called after a converged fit for every measurement, in order, on the caller's
  /// thread (conescan-fit --residuals).
  std::function<void(const residual_row&)> each_residual;
};

/// What to fit: the model, the parameters (start and held values, free flags), the measurements
/// and each head's noise.
struct fit_problem {
  const forward_model* model = nullptr;  ///< must point to a model for the fit's duration
  parameter_set parameters;
  /// The measurements, borrowed: they must outlive the fit (a month of telemetry is not copied).
  std::span<const observation> observations;
  std::vector<head_noise> noise;  ///< one per head
};

/// An observation after the fit: residuals measured minus predicted (deg) and normalised.
struct outlier {
  telemetry_sample sample;
  double chord_residual_deg = 0;
  double phase_residual_deg = 0;
  double normalised = 0;
};

/// Where a fit's time went (wall clock, s) and how many passes over the data it made: for the
/// benchmark and a verbose report. Not part of the JSON (a fit read back has zeros).
struct fit_timing {
  double setup_s = 0;          ///< checks and the start's pass
  double solve_s = 0;          ///< the rounds: Levenberg-Marquardt, noise, re-admission
  double linear_solver_s = 0;  ///< of which solving the normal equations
  double uncertainty_s = 0;    ///< the analysis and the outlier pass after convergence
  int linearizations = 0;      ///< passes with derivatives (Jets through the model)
  int value_passes = 0;        ///< passes with values only: start, noise, re-admission, outliers
};

/// Outliers of one head whose residuals in one component share a sign far more often than noise
/// would make them (two-sided binomial probability below systematic_probability): a systematic
/// effect the model does not describe (a shifted crossing, a glint), not noise.
struct systematic_effect {
  std::size_t head = 0;          ///< 0-based
  bool phase = false;            ///< the phase residuals (true) or the chord's
  std::size_t outliers = 0;      ///< the head's outliers
  std::size_t same_sign = 0;     ///< of which with the sign `sign`
  int sign = 1;                  ///< +1 or -1: the residuals' (measured minus predicted) sign
  double mean_residual_deg = 0;  ///< mean residual of the head's outliers in that component
  double probability = 0;        ///< of so many or more sharing a sign by chance
};
inline constexpr double systematic_probability = 1e-3;

/// A head's noise as declared and as its residuals show it.
struct head_noise_estimate {
  /// The declared crossing noise (deg; 0 when none is stated).
  double declared_deg = 0;
  /// The robust scale of the head's residuals in units of its declared 1 sigma (of the 1 deg
  /// crossing noise of unit weights when no noise is stated); NaN when not estimated (fewer than
  /// 20 measurements).
  double ratio = 0;
  /// The crossing noise that implies (deg): ratio times the declared noise, or times 1 deg
  /// without stated noise; NaN when not estimated or when the head states only a telemetry step.
  double estimated_deg = 0;
  /// The weights used: the declared 1 sigma times this.
  double weight_ratio = 1;
};

/// Telemetry left out before a fit because the Sun or the Moon blinds a head there (MODEL §13:
/// status sun, moon): per head, the rows the scene's --intrusions says were lost to each body
/// (whether the telemetry holds numbers there or nan). Empty without --intrusions. Set by the
/// scene's fit (scene_calibration/scene_fit.hpp), not by fit().
struct blinded_rows {
  std::vector<std::size_t> sun;   ///< per head
  std::vector<std::size_t> moon;  ///< per head
};

/// A converged fit.
struct fit_result {
  uncertainty_report uncertainty;
  double chi2_dof = 0;
  std::size_t residual_count = 0;
  std::size_t dof = 0;
  std::vector<double> residual_rms_deg;  ///< per head, chord and phase together; NaN: no data
  std::vector<std::size_t> observations_per_head;  ///< measurements used, per head
  std::size_t dropped_at_start = 0;  ///< measurements the model could not predict at the start
  /// Of those, re-admitted: predictable at a later solution, tested again there and fitted.
  std::size_t readmitted = 0;
  /// Per head, measurements the model cannot predict at the solution, left out (a warning when
  /// more than 1 % of a head's).
  std::vector<std::size_t> dropped_per_head;
  robust_loss loss = robust_loss::none;  ///< the loss used (none when the noise is not stated)
  double huber_scale = 0;
  /// No stated noise: the weights start from a 1 deg crossing noise (and the noise estimated
  /// from the data scales them, noise[k].weight_ratio).
  bool unit_weights = false;
  double outlier_threshold = 0;
  std::size_t outlier_count = 0;
  std::vector<outlier> worst_outliers;  ///< largest first
  std::vector<systematic_effect> systematic;
  int iterations = 0;
  std::string solver_message;
  noise_scaling scaling = noise_scaling::declared;
  std::vector<head_noise_estimate> noise;  ///< per head
  /// What a reader must not miss, one sentence each: chi2/dof or a head's noise ratio far from 1
  /// (warning_limits), and what the caller adds (scene_fit: an estimate outside the scene's
  /// domain for that parameter).
  std::vector<std::string> warnings;
  fit_timing timing;
  blinded_rows blinded;  ///< left out before the fit (--intrusions)
};

/// A fit that stopped without converging: its last state, never to be reported as an estimate.
struct unconverged_fit {
  parameter_set last_state;  ///< parameter values where it stopped (free flags as given)
  int iterations = 0;
  double cost = 0;  ///< half the sum of (robust) squared whitened residuals
  std::string solver_message;
  blinded_rows blinded;  ///< left out before the fit (--intrusions)
};

using fit_outcome = std::variant<fit_result, unconverged_fit>;

/// Fits the free parameters. Errors (bad input, exit 2): no free parameter, a head's noise
/// negative or non-finite, heads with and without stated noise, an observation's head beyond
/// the parameter set's, no observation the model can predict at the start, fewer residuals than
/// free coordinates.
checked<fit_outcome> fit(const fit_problem& problem, const fit_options& options);

/// Experiment design: the 1 sigma each free parameter would reach from the Fisher information
/// J^T W J at the parameters' values with the stated noise (no data, no chi2 scaling), with the
/// same observability verdict. Samples the model cannot predict are left out and counted.
struct design_result {
  uncertainty_report uncertainty;
  std::size_t residual_count = 0;
  std::size_t dropped = 0;
  blinded_rows blinded;  ///< planned samples left out (--intrusions)
};
checked<design_result> predict_uncertainty(const forward_model& model,
                                           const parameter_set& parameters,
                                           const std::vector<telemetry_sample>& samples,
                                           const std::vector<head_noise>& noise, int threads = 2);

}  // namespace conescan::calibration
