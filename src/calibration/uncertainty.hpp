// From the information matrix at the solution to what the data determine: every parameter's 1
// sigma, their correlation, the condition number, and the combinations the data cannot separate
// (MODEL §11). Shared by a fit (the information scaled by the residual variance) and by
// experiment design (the Fisher information alone).
//
// The normalised information matrix. J^T W J in the parameters' own units mixes deg and km, so
// its eigenvalues and condition number would change with the units. Every statement here uses
// instead N = D J^T W J D with D = diag(1 / sqrt((J^T W J)_ii)): each coordinate measured in its
// own 1 sigma when all the others are held (N has a unit diagonal, its eigenvalues sum to the
// number of coordinates and do not depend on units or on the noise level). An eigenvector v of N
// with eigenvalue lambda is a combination sum v_i theta_i / s_i (s_i = D_ii) whose 1 sigma is
// 1 / sqrt(lambda) times what each coordinate would have alone: lambda near 0 means the data
// move the combination hardly at all.
//
// The verdict. A combination is unobservable when lambda < 1e-8 lambda_max: its 1 sigma is
// more than 1e4 times the coordinates' own, so that a model error of 1e-4 of the noise in the
// residuals could move it by its whole 1 sigma; and the threshold lies five orders above the
// rounding floor of the eigenvalues of N in double (about 1e-13 lambda_max for the Jacobians of
// automatic differentiation), so an exact degeneracy (two parameters that enter only through
// their sum: lambda of order 1e-17) always falls below it. A coordinate is involved in such a
// combination when its component exceeds 1e-6 in magnitude (rounding leaves components of order
// 1e-16 / the eigenvalue gap, below 1e-9 for gaps above the threshold). The covariance is the
// pseudo-inverse of N on the observable eigenvectors; it is exact for every coordinate that is
// not involved (its value is an estimable function), and meaningless for those that are:
// their estimates are withheld (never an estimate without its uncertainty), the combinations
// say what the data could not separate.
//
// The misalignment. A cartesian head's (x, y) = (sigma cos phi_A, sigma sin phi_A) are reported
// as sigma = hypot(x, y) and phi_A = atan2(y, x), their covariance by linear propagation
// through the Jacobian of that map. phi_A is determined only when sigma >= 3 times its own
// 1 sigma: for a true sigma of 0 the estimated sigma / 1 sigma follows a Rayleigh law and
// exceeds 3 with probability exp(-4.5) = 1.1 %; below it phi_A's linearised 1 sigma (about
// 1 sigma(sigma) / sigma rad) exceeds 19 deg and the linearisation no longer holds, so phi_A is
// withheld as undetermined (sigma itself is still reported, its estimate biased upwards by the
// Rice law at such low ratios). At sigma = 0 exactly, sigma's 1 sigma is taken along the
// components' most uncertain direction.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "calibration/layout.hpp"

namespace conescan::calibration {

inline constexpr double unobservable_eigenvalue_ratio = 1e-8;
inline constexpr double involvement_component = 1e-6;
inline constexpr double phase_detection_ratio = 3;

/// One parameter as a report gives it.
struct parameter_estimate {
  std::string name;
  std::string unit;
  bool free = false;
  /// false: the data do not determine it; estimate and sigma are NaN and `withheld` says why.
  bool determined = true;
  double estimate = 0;  ///< the held value when not free
  double sigma = 0;     ///< 1 sigma; 0 when held
  std::string withheld;
  std::size_t index = 0;  ///< the parameter's index (parameters.hpp)
};

/// One segment's value of a drifting parameter.
struct drift_segment {
  double start_s = 0;  ///< t_s where it starts (the first segment: the first measurement's time)
  double end_s = 0;    ///< where the next starts (the last also holds everything after it)
  std::size_t observations = 0;  ///< measurements fitted in it (0 in an experiment design)
  parameter_estimate value;      ///< named "horizon-km[3]" for segment 3
};

/// A drifting parameter's history: one value per segment, with its 1 sigma.
struct drift_history {
  std::size_t parameter = 0;  ///< its index
  std::string name;
  std::string unit;
  double segment_s = 0;
  std::vector<drift_segment> segments;
};

/// A combination of coordinates the data cannot separate: components of a unit eigenvector of
/// the normalised information matrix (by coordinate name, largest first, the largest positive),
/// and its eigenvalue over the largest.
struct unobservable_combination {
  std::vector<std::pair<std::string, double>> components;
  double eigenvalue_ratio = 0;
};

struct uncertainty_report {
  /// Every parameter, by parameter index; a drifting one is not determined as one value (NaN,
  /// withheld "drifts: ...") and has its history in `drift`.
  std::vector<parameter_estimate> parameters;
  std::vector<std::size_t> free_parameters;  ///< indices of the free ones, in index order
  /// What the fit estimated, in coordinate order: the free parameters, and a drifting one's value
  /// in each segment in its place ("horizon-km[0]", ...; a drifting sigma and phase alternate,
  /// segment by segment). Without drifting parameters, parameters[free_parameters[i]].
  std::vector<parameter_estimate> reported;
  std::vector<std::vector<double>> correlation;  ///< over `reported`; NaN where withheld
  std::vector<drift_history> drift;              ///< per drifting parameter, in index order
  double condition = 0;  ///< lambda_max / lambda_min of the normalised matrix (+inf: singular)
  std::vector<unobservable_combination> unobservable;
  /// The estimated coordinates (slot_name), their values and covariance (NaN rows and columns
  /// for coordinates involved in an unobservable combination): what a correction propagates.
  std::vector<std::string> coordinate_names;
  std::vector<double> coordinate_values;
  std::vector<std::vector<double>> coordinate_covariance;
  std::size_t rank = 0;  ///< number of observable eigenvectors
};

/// The report of a fit or an experiment design.
///   layout, slots, x: the fit's layout, every slot's value (the held ones as held), and the
///     estimated coordinates' values (the estimate, or the nominal values);
///   information: sum over measurements of w J^T J, J the whitened residuals' Jacobian over the
///     layout's coordinates (in their order), w the robust weight (1 without a robust loss);
///   variance_scale: the residual variance chi2/dof of a fit, 1 for the Fisher information.
uncertainty_report analyse_uncertainty(const estimation_layout& layout,
                                       const std::vector<double>& slots,
                                       const std::vector<double>& x,
                                       const Eigen::MatrixXd& information, double variance_scale);

}  // namespace conescan::calibration
