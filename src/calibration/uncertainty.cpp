#include "calibration/uncertainty.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "text/number_text.hpp"

namespace conescan::calibration {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t sigma_offset = static_cast<std::size_t>(head_parameter::sigma);
constexpr std::size_t phase_offset = static_cast<std::size_t>(head_parameter::phase);

/// N = D H D and D (1 for a coordinate the data do not touch at all, whose row of N is then 0).
struct normalised_information {
  Eigen::VectorXd scale;
  Eigen::MatrixXd matrix;
};

normalised_information normalise(const Eigen::MatrixXd& information) {
  const Eigen::Index p = information.rows();
  Eigen::VectorXd scale(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    const double h = information(i, i);
    scale(i) = h > 0 ? 1 / std::sqrt(h) : 1.0;
  }
  return {scale, scale.asDiagonal() * information * scale.asDiagonal()};
}

/// Eigenvalues ascending, eigenvectors as columns; the unobservable ones are the first `count`.
struct spectrum {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  Eigen::Index unobservable_count = 0;
  double largest = 0;
};

spectrum decompose(const Eigen::MatrixXd& normalised) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(normalised);
  spectrum s{solver.eigenvalues(), solver.eigenvectors(), 0, 0};
  s.largest = s.values(s.values.size() - 1);
  const double threshold = unobservable_eigenvalue_ratio * s.largest;
  while (s.unobservable_count < s.values.size() &&
         (!(s.largest > 0) || s.values(s.unobservable_count) < threshold))
    ++s.unobservable_count;
  return s;
}

std::vector<bool> involved_coordinates(const spectrum& s) {
  std::vector<bool> involved(static_cast<std::size_t>(s.values.size()), false);
  for (Eigen::Index e = 0; e < s.unobservable_count; ++e)
    for (Eigen::Index i = 0; i < s.values.size(); ++i)
      if (std::abs(s.vectors(i, e)) > involvement_component)
        involved[static_cast<std::size_t>(i)] = true;
  return involved;
}

/// scale D N+ D over the observable eigenvectors.
Eigen::MatrixXd pseudo_inverse_covariance(const normalised_information& n, const spectrum& s,
                                          double variance_scale) {
  const Eigen::Index p = s.values.size();
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index e = s.unobservable_count; e < p; ++e)
    inverse += s.vectors.col(e) * s.vectors.col(e).transpose() / s.values(e);
  const Eigen::MatrixXd c =
      variance_scale * (n.scale.asDiagonal() * inverse * n.scale.asDiagonal());
  return (c + c.transpose()) / 2;  // exactly symmetric, so that correlations are too
}

std::vector<unobservable_combination> combinations(const estimation_layout& layout,
                                                   const spectrum& s) {
  std::vector<unobservable_combination> out;
  for (Eigen::Index e = 0; e < s.unobservable_count; ++e) {
    Eigen::VectorXd v = s.vectors.col(e);
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    if (v(largest) < 0) v = -v;
    unobservable_combination c;
    for (Eigen::Index i = 0; i < v.size(); ++i)
      if (std::abs(v(i)) > involvement_component)
        c.components.emplace_back(coordinate_name(layout, static_cast<std::size_t>(i)), v(i));
    std::stable_sort(c.components.begin(), c.components.end(), [](const auto& a, const auto& b) {
      return std::abs(a.second) > std::abs(b.second);
    });
    c.eigenvalue_ratio = s.largest > 0 ? std::max(s.values(e), 0.0) / s.largest : 0.0;
    out.push_back(std::move(c));
  }
  return out;
}

/// Estimates and covariance of the reported parameters (sigma, phi_A for a cartesian head's
/// (x, y); the coordinates themselves otherwise), and which of them are withheld and why.
struct reported {
  std::vector<double> estimate;  ///< by coordinate position
  Eigen::MatrixXd covariance;
  std::vector<std::string> withheld;  ///< "" when determined
};

/// The Jacobian of (sigma, phi_A in deg) with respect to (x, y) (deg); at sigma = 0 the sigma
/// row follows the components' most uncertain direction.
Eigen::Matrix2d polar_jacobian(double x, double y, const Eigen::Matrix2d& covariance_xy) {
  Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
  const double sigma = std::hypot(x, y);
  if (sigma > 0) {
    g << x / sigma, y / sigma, -y / (sigma * sigma) / radians_per_degree,
        x / (sigma * sigma) / radians_per_degree;
  } else {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance_xy);
    g.row(0) = solver.eigenvectors().col(1).transpose();
    g(1, 0) = g(1, 1) = nan;
  }
  return g;
}

/// True when `slot` is slot `offset` (sigma or phase) of a head estimated as components.
bool cartesian_slot(const estimation_layout& layout, std::size_t slot, std::size_t offset) {
  return slot < layout.earth_block() && slot % head_parameter_count == offset &&
         layout.forms[slot / head_parameter_count] == misalignment_form::cartesian;
}

const char* const unobservable_reason = "unobservable: in a combination the data cannot separate";

/// phi_A of a cartesian head is withheld while sigma < 3 times its 1 sigma (uncertainty.hpp).
void withhold_unresolved_phases(const estimation_layout& layout, reported& r) {
  for (std::size_t i = 1; i < layout.coordinates.size(); ++i) {
    if (!cartesian_slot(layout, layout.coordinates[i], phase_offset) || !r.withheld[i].empty())
      continue;
    const auto at = static_cast<Eigen::Index>(i);
    const double sigma_sigma = std::sqrt(r.covariance(at - 1, at - 1));
    if (!(r.estimate[i - 1] >= phase_detection_ratio * sigma_sigma))
      r.withheld[i] = "undetermined: sigma is below 3 times its 1 sigma, phi_A is not resolved";
  }
}

/// The value each coordinate reports: a cartesian pair as sigma = hypot(x, y) and phi_A =
/// atan2(y, x) (0 at sigma = 0), a free phi_A wrapped into (-180, 180] deg, the others as they are.
std::vector<double> reported_values(const estimation_layout& layout, const std::vector<double>& x) {
  std::vector<double> values(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t slot = layout.coordinates[i];
    if (cartesian_slot(layout, slot, sigma_offset))
      values[i] = std::hypot(x[i], x[i + 1]);
    else if (cartesian_slot(layout, slot, phase_offset))
      values[i] = wrap_deg(std::atan2(x[i], x[i - 1]) / radians_per_degree);
    else if (slot < layout.earth_block() && slot % head_parameter_count == phase_offset)
      values[i] = wrap_deg(x[i]);
    else
      values[i] = x[i];
  }
  return values;
}

reported report_parameters(const estimation_layout& layout, const std::vector<double>& x,
                           const Eigen::MatrixXd& covariance, const std::vector<bool>& involved) {
  const std::size_t p = layout.coordinates.size();
  reported r{reported_values(layout, x), covariance, std::vector<std::string>(p)};
  const auto size = static_cast<Eigen::Index>(p);
  Eigen::MatrixXd g = Eigen::MatrixXd::Identity(size, size);
  for (std::size_t i = 0; i < p; ++i) {
    if (involved[i]) r.withheld[i] = unobservable_reason;
    // A cartesian head's (x, y), coordinates i and i + 1, become (sigma, phi_A); either
    // involved withholds both.
    if (!cartesian_slot(layout, layout.coordinates[i], sigma_offset)) continue;
    const auto at = static_cast<Eigen::Index>(i);
    g.block<2, 2>(at, at) = polar_jacobian(x[i], x[i + 1], covariance.block<2, 2>(at, at));
    if (involved[i] || involved[i + 1]) r.withheld[i] = r.withheld[i + 1] = unobservable_reason;
  }
  // Rows of g that are NaN (phi_A at sigma = 0) would poison every product: propagate with them
  // zeroed (phi_A is then withheld below, sigma = 0 < 3 times its 1 sigma).
  const Eigen::MatrixXd g_finite = g.unaryExpr([](double v) { return std::isfinite(v) ? v : 0.0; });
  const Eigen::MatrixXd propagated = g_finite * covariance * g_finite.transpose();
  r.covariance = (propagated + propagated.transpose()) / 2;  // exactly symmetric
  withhold_unresolved_phases(layout, r);
  for (std::size_t i = 0; i < p; ++i) {
    if (r.withheld[i].empty()) continue;
    const auto at = static_cast<Eigen::Index>(i);
    r.covariance.row(at).setConstant(nan);
    r.covariance.col(at).setConstant(nan);
  }
  return r;
}

std::vector<std::vector<double>> to_rows(const Eigen::MatrixXd& m) {
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      rows[static_cast<std::size_t>(i)].push_back(m(i, j));
  return rows;
}

std::vector<std::vector<double>> correlation_of(const Eigen::MatrixXd& covariance) {
  Eigen::MatrixXd c = covariance;
  for (Eigen::Index i = 0; i < c.rows(); ++i)
    for (Eigen::Index j = 0; j < c.cols(); ++j)
      c(i, j) = i == j && std::isfinite(covariance(i, i))
                    ? 1.0
                    : covariance(i, j) / std::sqrt(covariance(i, i) * covariance(j, j));
  return to_rows(c);
}

/// Each drifting parameter's history from the reported segment values.
std::vector<drift_history> histories(const estimation_layout& layout,
                                     const std::vector<parameter_estimate>& reported) {
  std::vector<drift_history> out;
  for (std::size_t slot = 0; slot < layout.free.size(); ++slot) {
    if (!layout.free[slot] || !layout.drifts(slot)) continue;
    drift_history h{slot,
                    parameter_name(slot, layout.head_count),
                    std::string(parameter_unit(slot, layout.head_count)),
                    layout.segment_s[slot],
                    {}};
    for (std::size_t i = 0; i < layout.coordinates.size(); ++i) {
      if (layout.coordinates[i] != slot) continue;
      const double k = static_cast<double>(layout.coordinate_segment[i]);
      // The last segment ends at the last measurement, which it holds.
      const double end = layout.coordinate_segment[i] + 1 == layout.segments[slot]
                             ? layout.t_last_s
                             : layout.t0_s + (k + 1) * layout.segment_s[slot];
      h.segments.push_back({layout.t0_s + k * layout.segment_s[slot], end, 0, reported[i]});
    }
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace

uncertainty_report analyse_uncertainty(const estimation_layout& layout,
                                       const std::vector<double>& slots,
                                       const std::vector<double>& x,
                                       const Eigen::MatrixXd& information, double variance_scale) {
  uncertainty_report report;
  if (information.rows() == 0) return report;
  const normalised_information n = normalise(information);
  const spectrum s = decompose(n.matrix);
  const std::vector<bool> involved = involved_coordinates(s);
  Eigen::MatrixXd coordinate_covariance = pseudo_inverse_covariance(n, s, variance_scale);
  const reported r = report_parameters(layout, x, coordinate_covariance, involved);

  const std::vector<double> values = parameters_from_slots(layout, slots);
  for (std::size_t index = 0; index < values.size(); ++index) {
    report.parameters.push_back({parameter_name(index, layout.head_count),
                                 std::string(parameter_unit(index, layout.head_count)), false, true,
                                 values[index], 0.0, "", index,
                                 physics_absent(index, layout.head_count, values[index])});
    if (layout.free[index]) report.free_parameters.push_back(index);
  }
  for (std::size_t i = 0; i < layout.coordinates.size(); ++i) {
    const std::size_t slot = layout.coordinates[i];
    const auto at = static_cast<Eigen::Index>(i);
    parameter_estimate e = report.parameters[slot];
    e.free = true;
    e.determined = r.withheld[i].empty();
    e.withheld = r.withheld[i];
    e.estimate = e.determined ? r.estimate[i] : nan;
    e.sigma = e.determined ? std::sqrt(r.covariance(at, at)) : nan;
    if (layout.drifts(slot)) e.name += "[" + std::to_string(layout.coordinate_segment[i]) + "]";
    report.reported.push_back(e);
    if (!layout.drifts(slot)) report.parameters[slot] = e;
  }
  for (std::size_t slot : report.free_parameters) {
    if (!layout.drifts(slot)) continue;
    parameter_estimate& e = report.parameters[slot];
    e.free = true;
    e.determined = false;
    e.estimate = e.sigma = nan;
    const std::size_t count = layout.segments[slot];
    e.withheld = "drifts: one value in each of " + std::to_string(count) +
                 (count == 1 ? " segment of " : " segments of ") +
                 text::shortest_text(layout.segment_s[slot]) + " s (its history)";
  }
  report.drift = histories(layout, report.reported);
  report.correlation = correlation_of(r.covariance);
  const double smallest = s.values(0);
  report.condition = smallest > 0 ? s.largest / smallest : std::numeric_limits<double>::infinity();
  report.unobservable = combinations(layout, s);
  for (std::size_t i = 0; i < layout.coordinates.size(); ++i) {
    report.coordinate_names.push_back(coordinate_name(layout, i));
    report.coordinate_keys.push_back(coordinate_key_of(layout, i));
    report.coordinate_values.push_back(involved[i] ? nan : x[i]);
    if (involved[i]) {
      const auto at = static_cast<Eigen::Index>(i);
      coordinate_covariance.row(at).setConstant(nan);
      coordinate_covariance.col(at).setConstant(nan);
    }
  }
  report.coordinate_covariance = to_rows(coordinate_covariance);
  report.rank = static_cast<std::size_t>(s.values.size() - s.unobservable_count);
  return report;
}

namespace {

/// The global coordinate carrying `slot` (cartesian or not as asked), if any.
std::optional<std::size_t> global_coordinate(const uncertainty_report& u, std::size_t slot,
                                             bool cartesian) {
  for (std::size_t i = 0; i < u.coordinate_keys.size(); ++i) {
    const coordinate_key& key = u.coordinate_keys[i];
    if (key.slot == slot && !key.segment && key.cartesian == cartesian) return i;
  }
  return std::nullopt;
}

std::size_t head_count_of(const uncertainty_report& u) {
  return (u.parameters.size() - earth_parameter_count) / head_parameter_count;
}

}  // namespace

std::optional<std::size_t> find_coordinate(const uncertainty_report& u, std::size_t head,
                                           head_parameter p) {
  if (head >= head_count_of(u)) return std::nullopt;
  return global_coordinate(u, parameter_index(head, p), false);
}

std::optional<std::size_t> find_coordinate(const uncertainty_report& u, std::size_t head,
                                           misalignment_axis axis) {
  if (head >= head_count_of(u)) return std::nullopt;
  const head_parameter slot =
      axis == misalignment_axis::x ? head_parameter::sigma : head_parameter::phase;
  return global_coordinate(u, parameter_index(head, slot), true);
}

std::optional<std::size_t> find_coordinate(const uncertainty_report& u, earth_parameter p) {
  return global_coordinate(u, parameter_index(head_count_of(u), p), false);
}

}  // namespace conescan::calibration
