#include "calibration/solver.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "calibration/report.hpp"

namespace conescan::calibration {

namespace {

constexpr double initial_lambda = 1e-3;
constexpr double rounding_tolerance = 1e-15;
constexpr double step_tolerance = 1e-12;
/// Below this fall of chi2 (of the residual variance) a rejected step ends the fit (solver.hpp).
constexpr double resolution_tolerance = 1e-6;
constexpr double diagonal_floor = 1e-12;

/// The diagonal scaling D of the damping.
Eigen::VectorXd damping_scale(const Eigen::MatrixXd& h) {
  Eigen::VectorXd d = h.diagonal().cwiseMax(0.0);
  const double largest = d.size() ? d.maxCoeff() : 0.0;
  const double floor = largest > 0 ? diagonal_floor * largest : 1.0;
  return d.cwiseMax(floor);
}

/// The solution of (H + lambda D) delta = -g; with Cholesky, LDL^T when that fails.
Eigen::VectorXd damped_step(const Eigen::MatrixXd& h, const Eigen::VectorXd& g,
                            const Eigen::VectorXd& d, double lambda, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd a = h;
  a.diagonal() += lambda * d;
  Eigen::LLT<Eigen::MatrixXd> llt(a);
  Eigen::VectorXd step = llt.info() == Eigen::Success ? Eigen::VectorXd(llt.solve(-g))
                                                      : Eigen::VectorXd(a.ldlt().solve(-g));
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return step;
}

std::size_t fitted_count(const passes::normal_equations& n) {
  std::size_t total = 0;
  for (std::size_t c : n.count) total += c;
  return total;
}

/// The convergence message's first part: the Gauss-Newton step's fall of chi2.
std::string gauss_newton_fall(double decrement, double chi2) {
  return "the Gauss-Newton step would lower chi2 by " + short_number(decrement, 3) + " (chi2 " +
         short_number(chi2, 6) + ")";
}

}  // namespace

solve_outcome levenberg_marquardt(const passes::setup& s, const passes::inclusion& fitted,
                                  Eigen::VectorXd x, int max_iterations, double tolerance) {
  solve_outcome out;
  out.x = std::move(x);
  out.at_x = passes::linearize(s, fitted, out.x);
  out.linearizations = 1;
  if (out.at_x.failed != 0) {
    out.message = "the model cannot predict every fitted measurement at the start";
    return out;
  }
  const double residuals = 2.0 * static_cast<double>(fitted_count(out.at_x));
  double lambda = initial_lambda, nu = 2;
  bool at_new_point = true;
  double decrement = 0;  // the Gauss-Newton step's chi2 fall at the point the iteration stands on
  for (;;) {
    const passes::normal_equations& n = out.at_x;
    const Eigen::VectorXd d = damping_scale(n.h);
    if (at_new_point) {
      const Eigen::VectorXd newton = damped_step(n.h, n.g, d, diagonal_floor, out.linear_solver_s);
      decrement = -n.g.dot(newton);
      const double chi2 = 2 * n.cost;
      if (!(decrement > tolerance * chi2 / residuals) || !(decrement > rounding_tolerance * chi2)) {
        out.converged = true;
        out.message = gauss_newton_fall(decrement, chi2);
        return out;
      }
    }
    if (out.iterations >= max_iterations) {
      out.message = "the iteration limit (" + std::to_string(max_iterations) + ") was reached";
      return out;
    }
    ++out.iterations;
    const Eigen::VectorXd step = damped_step(n.h, n.g, d, lambda, out.linear_solver_s);
    const double predicted = -(n.g.dot(step) + 0.5 * step.dot(n.h * step));
    passes::normal_equations trial = passes::linearize(s, fitted, out.x + step);
    ++out.linearizations;
    if (trial.failed == 0 && trial.cost < n.cost) {
      const double rho = predicted > 0 ? (n.cost - trial.cost) / predicted : 1.0;
      out.x += step;
      out.at_x = std::move(trial);
      lambda *= std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3));
      nu = 2;
      at_new_point = true;
      continue;
    }
    at_new_point = false;
    if (!(decrement > resolution_tolerance * 2 * n.cost / residuals)) {
      out.converged = true;
      out.message = gauss_newton_fall(decrement, 2 * n.cost) +
                    ", and no step lowers the cost: the model's own resolution";
      return out;
    }
    if (step.norm() <= step_tolerance * (out.x.norm() + step_tolerance)) {
      out.converged = true;
      out.message = "no step lowers the cost and the step is below 1e-12 of the coordinates";
      return out;
    }
    lambda *= nu;
    nu *= 2;
  }
}

}  // namespace conescan::calibration
