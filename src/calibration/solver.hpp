// Levenberg-Marquardt on the streamed normal equations of passes.hpp: the estimator's solver
// (estimator.hpp), in place of a Ceres problem that holds every residual block and its
// Jacobian (0.8 KB per measurement: a month of 1 Hz telemetry from two heads would need 4 GB).
//
// From coordinates x with normal equations H, g and cost c (passes::linearize), each iteration
// solves (H + lambda D) delta = -g, D the diagonal of H (floored at 1e-12 of its largest entry:
// a coordinate the data do not touch does not move), and linearises again at x + delta: the step
// is taken when the cost falls, and lambda then shrinks by max(1/3, 1 - (2 rho - 1)^3) (rho the
// actual over the predicted fall); otherwise lambda grows by nu = 2, 4, 8, ... (Nielsen's rule,
// as Ceres' own Levenberg-Marquardt). lambda starts at 1e-3. A step where the model cannot
// predict a fitted measurement is not taken (Ceres' behaviour too).
//
// Convergence, tested at every point the iteration stands on:
//  - the Gauss-Newton step from there would lower chi2 = 2 c by less than 1e-10 (`tolerance`) of
//    the residual variance 2 c / (residuals): the coordinates are within 1e-5 of their 1 sigma
//    of the minimum;
//    or by less than 1e-15 of chi2 itself (the sum's own rounding: noise-free data);
//  - or a step is not taken where the Gauss-Newton step would lower chi2 by less than 1e-6 of
//    the residual variance (the coordinates within 1e-3 of their 1 sigma): the model's own
//    resolution, not the data, then decides the cost's last digits. A model whose predictions
//    are interpolated and rebuilt as the parameters move (the fit's time series of the chain,
//    docs/CALIBRATION.md) moves chi2 by some 6e-7 from step to step (a day of a pencil with lag,
//    172 800 residuals), and the steps below it, a third of them rejected, had gone on until
//    lambda shrank them to nothing: 18 iterations where 7 reach the same point within 1e-3 sigma;
//  - or a step not taken is below 1e-12 of the coordinates (nothing left to move).
// Not converged: max_iterations steps tried without reaching either.
#pragma once

#include <Eigen/Core>
#include <string>

#include "calibration/passes.hpp"

namespace conescan::calibration {

inline constexpr double final_tolerance = 1e-10;
inline constexpr double rough_tolerance = 1e-2;

struct solve_outcome {
  bool converged = false;
  int iterations = 0;  ///< steps tried (taken or not)
  std::string message;
  Eigen::VectorXd x;              ///< the last point
  passes::normal_equations at_x;  ///< its normal equations
  int linearizations = 0;
  double linear_solver_s = 0;
};

/// `tolerance`: the statistical tolerance (1e-10 for a final solution; a looser one, 1e-2 (the
/// coordinates within 0.1 of their 1 sigma), for a solution whose residuals only set the noise
/// of the next round).
solve_outcome levenberg_marquardt(const passes::setup& s, const passes::inclusion& fitted,
                                  Eigen::VectorXd x, int max_iterations,
                                  double tolerance = final_tolerance);

}  // namespace conescan::calibration
