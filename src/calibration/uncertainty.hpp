// From the information matrix at the solution to what the data determine (MODEL §11): every
// parameter's 1 sigma, their correlation, the condition number, and the combinations the data
// cannot separate. Shared by a fit (the information scaled by the residual variance) and by
// experiment design (the Fisher information alone).
//
// The contract (docs/CALIBRATION.md, "Uncertainty and observability" and "The misalignment",
// gives the reasons and the measurements). Every statement is about the normalised information
// N = D J^T W J D, D = diag(1 / sqrt((J^T W J)_ii)), whose eigenvalues depend neither on the
// units nor on the noise. An eigenvector of N whose eigenvalue is below
// unobservable_eigenvalue_ratio times the largest is a combination the data cannot separate; a
// coordinate whose component in it exceeds involvement_component is withheld (estimate and 1 sigma
// NaN, with the reason: never an estimate without its uncertainty); the others have the
// pseudo-inverse of N on the observable eigenvectors, exact for them. A cartesian head's (x, y)
// are reported as sigma = hypot(x, y) and phi_A = atan2(y, x) by linear propagation; phi_A is
// withheld as undetermined below sigma = phase_detection_ratio times its 1 sigma.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
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
  /// A physics parameter the scene does not have (parameters.hpp: its value NaN, held):
  /// reports and the fit's JSON leave it out.
  bool absent = false;
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
  /// The same coordinates by (head, parameter) (layout.hpp): what a program looks them up by
  /// (find_coordinate), the names being for people and files.
  std::vector<coordinate_key> coordinate_keys;
  std::vector<double> coordinate_values;
  std::vector<std::vector<double>> coordinate_covariance;
  std::size_t rank = 0;  ///< number of observable eigenvectors
};

/// A misalignment component, as a head whose sigma and phase are both free is estimated
/// (layout.hpp): x = sigma cos phi_A, y = sigma sin phi_A.
enum class misalignment_axis : unsigned char { x, y };

/// The index in `u`'s coordinates of the global value of head `head`'s parameter `p`; nullopt
/// when the fit did not estimate it as one coordinate: held, drifting, a head beyond the report's,
/// or the sigma or phase of a cartesian head (estimated as its misalignment's x and y).
std::optional<std::size_t> find_coordinate(const uncertainty_report& u, std::size_t head,
                                           head_parameter p);
/// The same for head `head`'s misalignment component `axis` (estimated where sigma and phase are
/// both free).
std::optional<std::size_t> find_coordinate(const uncertainty_report& u, std::size_t head,
                                           misalignment_axis axis);
/// The same for the Earth's parameter `p`.
std::optional<std::size_t> find_coordinate(const uncertainty_report& u, earth_parameter p);

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
