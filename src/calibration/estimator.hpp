// The estimator of MODEL §11: weighted nonlinear least squares over the telemetry's chords and
// phases, with a robust loss, Jacobians by automatic differentiation (ceres::Jet through the
// model), Levenberg-Marquardt on normal equations streamed from the data (solver.hpp,
// passes.hpp: the memory of a fit is that of its telemetry), and the uncertainty and
// observability of uncertainty.hpp; and experiment design, the same analysis from the Fisher
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
//
// Noise from the data. The declared noise is a claim, and a wrong one breaks both the weights
// and the robust loss's threshold (with the noise declared 10 times too small every residual lies
// beyond the threshold, the loss turns into least absolute values and chi2/dof cannot exceed
// a^2 / 2 = 4.5, so the 1 sigma come out 3 times too small). So after a first fit with the
// declared weights each head's noise is estimated from its own residuals, robustly: the median
// of the absolute whitened residuals (chord and phase pooled, in units of the declared 1 sigma)
// over the normal law's 0.674490, a scale that the outliers and the crossing biases of a few
// measurements hardly move (the median absolute value about zero rather than about the median:
// a residual offset that the free parameters cannot absorb is an error the model does not
// describe, and counting it as noise widens the 1 sigma rather than hiding it). The weights of
// each head are then its declared 1 sigma times that ratio (fit_options::noise_scaling; the
// alternatives are kept for the comparison of docs/CALIBRATION.md), the fit is run again from
// the first solution, and again until no head's ratio moves by more than 2 % (at most 4 fits).
// A head with fewer than 20 measurements, or whose ratio is below 1e-6 (noise-free data), keeps
// its declared weights.
//
// Re-admission. A measurement the model cannot predict at the start (a scan that misses the
// Earth for a start far from the truth: sigma = 20 deg, dgamma = -30 deg) is left out of the
// first fit, and tested again at its solution: those predictable there rejoin, and the fit runs
// again, until none rejoins (each round from the last solution). What stays out is counted per
// head, with a warning above 1 % of a head's measurements.
//
// Systematic outliers. The outliers of a head are counted by the sign of their chord and phase
// residuals; noise gives either sign alike, so when one sign holds far more of them than chance
// would (binomial probability below 1e-3) they are reported as a systematic effect, with a
// warning: the robust loss bounds each one's pull, but many pulling the same way still move
// the estimate, and their count says so.
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
