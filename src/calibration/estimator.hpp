// The estimator of MODEL §11: weighted nonlinear least squares over the telemetry's chords and
// phases, with a robust loss, Jacobians by automatic differentiation (Ceres), and the uncertainty
// and observability of uncertainty.hpp; and experiment design, the same analysis from the Fisher
// information alone.
//
// Residuals. Each observation (one head in one row) gives two: the chord's and the phase's,
// measured minus predicted (the phase's modulo 360 deg), each divided by its 1 sigma. Detector
// noise acts on each crossing independently (measurement_errors.hpp), so with a crossing noise n
// the chord has sqrt(2) n and the phase n / sqrt(2), and the two are uncorrelated
// (cov(out - in, (in + out) / 2) = (n^2 - n^2) / 2 = 0); a telemetry step lsb adds lsb^2 / 12 to
// each variance (uniform rounding). Heads without stated noise (n = lsb = 0): all heads of the
// fit must then have none, and the weights are those of a crossing noise of 1 deg (chord
// sqrt(2) deg, phase 1/sqrt(2) deg): the 1 sigma, scaled by the residual variance, does not
// depend on that choice; the robust loss is then off (its scale, in units of the noise, has no
// meaning) and the report says so. Mixing heads with and without noise is refused.
//
// Robust loss. Huber's, on each observation's whitened pair: rho(s) = s for s <= a^2, else
// 2 a sqrt(s) - a^2, s = r_chord^2 + r_phase^2, a = 3 (in units of the stated noise): a clean
// observation exceeds it with probability exp(-a^2 / 2) = 1.1 % (s is chi-square with 2
// degrees of freedom), so the fit keeps almost all of least squares' efficiency, while a 1 deg
// outlier at 0.01 deg noise (70 sigma) pulls with a weight a / sqrt(s) of 0.04. Huber's rather
// than a redescending loss (Cauchy) because it is convex: the fit reaches the same minimum from
// sigma = 0 however far the start's residuals are. fit_options::loss switches it off.
//
// Uncertainty with the loss: the weights w = rho'(s) of the solution (1 inside the threshold,
// a / sqrt(s) beyond it) enter the information sum w J^T J, and the residual variance is Huber's
// sum of squared influences, chi2 = sum w^2 s (which is the ordinary chi-square when no
// observation exceeds the threshold), over dof = residuals - rank. Without the loss, w = 1:
// MODEL §11's (J^T W J)^-1 chi2/dof exactly.
//
// Outliers: observations whose normalised residual sqrt(s / (chi2/dof)) exceeds 6 after the fit
// (for Gaussian noise exp(-18) = 1.5e-8 per observation: 0.003 false alarms in a day of two heads
// at 1 Hz), counted, the worst listed.
#pragma once

#include <cstddef>
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

/// The fit's settings (the program validates them: scales and threshold > 0, threads and
/// iterations >= 1).
struct fit_options {
  robust_loss loss = robust_loss::huber;
  double huber_scale = 3;        ///< a, in units of the stated noise
  double outlier_threshold = 6;  ///< normalised residual beyond which an observation is listed
  std::size_t outliers_listed = 10;
  int max_iterations = 100;
  int threads = 2;  ///< Ceres' num_threads, and the uncertainty pass's
};

/// What to fit: the model, the parameters (start and held values, free flags), the measurements
/// and each head's noise.
struct fit_problem {
  const forward_model* model = nullptr;  ///< must point to a model for the fit's duration
  parameter_set parameters;
  std::vector<observation> observations;
  std::vector<head_noise> noise;  ///< one per head
};

/// An observation after the fit: residuals measured minus predicted (deg) and normalised.
struct outlier {
  telemetry_sample sample;
  double chord_residual_deg = 0;
  double phase_residual_deg = 0;
  double normalised = 0;
};

/// Where a fit's time went (wall clock, s), and how often Ceres evaluated the model: for the
/// benchmark and a verbose report. Not part of the JSON (a fit read back has zeros).
struct fit_timing {
  double setup_s = 0;      ///< checks, the start's predictions, building the problem
  double solve_s = 0;      ///< ceres::Solve
  double residuals_s = 0;  ///< of which evaluating residuals only
  double jacobians_s = 0;  ///< of which evaluating residuals and Jacobians
  double linear_solver_s = 0;
  double uncertainty_s = 0;  ///< the information pass and the analysis after convergence
  int residual_evaluations = 0;
  int jacobian_evaluations = 0;
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
  std::vector<std::size_t> observations_per_head;
  std::size_t dropped_at_start = 0;      ///< observations the model could not predict at the start
  robust_loss loss = robust_loss::none;  ///< the loss used (none when the noise is not stated)
  double huber_scale = 0;
  bool unit_weights = false;  ///< no stated noise: weights of a 1 deg crossing noise
  double outlier_threshold = 0;
  std::size_t outlier_count = 0;
  std::vector<outlier> worst_outliers;  ///< largest first
  int iterations = 0;
  std::string solver_message;
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
