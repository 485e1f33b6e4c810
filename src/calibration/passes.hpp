// The passes of a fit over its measurements (the estimator's inside; estimator.hpp says what a
// fit does, this file how the data are walked).
//
// Nothing is kept per measurement but the observation itself and one byte saying whether it is
// fitted: each pass streams the measurements, on `threads` threads taking contiguous parts,
// and reduces what it needs as it goes — the normal equations (a p x p matrix and a p vector,
// p the estimated coordinates), histograms of the residuals, the worst outliers. So the memory
// of a fit is that of its telemetry, whatever its length (docs/CALIBRATION.md: a month of 1 Hz
// telemetry from two heads). The sums are taken over 64 parts whatever the threads and reduced
// in the parts' order, so a pass gives the same numbers, to the bit, on every run and on any
// number of threads.
//
// A measurement's whitened residuals are those of estimator.hpp: measured minus predicted, the
// phase's modulo 360 deg, each divided by its 1 sigma; its squared norm s enters Huber's loss
// rho(s) = s for s <= a^2, 2 a sqrt(s) - a^2 beyond, whose weight rho'(s) (1, or a / sqrt(s))
// multiplies its row of the normal equations (iteratively reweighted least squares: the same
// stationary point as the loss itself).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/layout.hpp"
#include "text/parallel_parts.hpp"

namespace conescan::calibration::passes {

using text::parallel_parts;  // the library's one parallel-for

/// Counts of |value| in bins of 1/256 octave from 2^-64 to 2^64 (beyond: the end bins), merged
/// across a pass's parts: a median without keeping the values (256 KiB, whatever their number).
/// Within a bin the values are taken as spread evenly (a bin is 0.27-0.39 % wide). Measured
/// against the exact median (tests/scene_calibration/test_calibration_noise.cpp, |x| of normal
/// samples): relative error 4.0e-4 at 100 values, 5.4e-4 at 1000, 2.5e-5 at a million, far below
/// the median's own scatter (1.17 / sqrt(n): 12 %, 3.7 %, 0.12 %). NaN and 0 count in the first
/// bin, infinities in the last.
class log_histogram {
 public:
  log_histogram();
  void add(double value);
  void merge(const log_histogram& other);
  std::size_t total() const noexcept { return total_; }
  /// The median of the |values| (NaN when empty).
  double median() const;

 private:
  static constexpr int per_octave = 256;
  static constexpr int lowest_exponent = -64;
  static constexpr int octaves = 128;
  static constexpr std::size_t bins = octaves * per_octave;
  static std::size_t bin_of(double a);
  static double lower(std::size_t bin);
  static double upper(std::size_t bin);

  std::vector<std::uint64_t> counts_;
  std::size_t total_ = 0;
};

/// What every pass needs, fixed for a pass.
struct setup {
  const forward_model* model = nullptr;
  std::span<const observation> observations;
  const estimation_layout* layout = nullptr;
  /// Every slot's value (layout.hpp): the held ones are read from here, the free ones from the
  /// coordinates a pass is given.
  std::vector<double> slots;
  std::vector<measurement_sigma> sigma;  ///< per head: the 1 sigma of the weights
  double huber_scale = 0;                ///< a (in units of the weights' 1 sigma); 0: no loss
  int threads = 1;
};

/// The fitted measurements: 1 fitted, 0 left out (the model cannot predict it).
using inclusion = std::vector<std::uint8_t>;

/// The normal equations of the fitted measurements at coordinates x, and what comes with them.
struct normal_equations {
  Eigen::MatrixXd h;       ///< sum of w J^T J over the coordinates (J of the whitened residuals)
  Eigen::VectorXd g;       ///< sum of w J^T r
  double cost = 0;         ///< half the sum of rho(s)
  double chi2 = 0;         ///< sum of w^2 s: Huber's sum of squared influences (s without the loss)
  std::size_t failed = 0;  ///< fitted measurements the model cannot predict at x
  std::vector<std::size_t> count;        ///< per head, fitted measurements
  std::vector<double> sum_squares_deg2;  ///< per head, chord^2 + phase^2 residuals (deg^2)
};

/// Linearises at x (automatic derivatives: ceres::Jet through the model). A pass with
/// failed != 0 holds no usable sums.
normal_equations linearize(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x);

/// Per head the median of the absolute residuals of the fitted measurements at x, chord and
/// phase pooled, each in units of `unit` (per head); NaN for a head with fewer than
/// `minimum_count` measurements. From a log_histogram per head.
std::vector<double> median_abs_residual(const setup& s, const inclusion& fitted,
                                        const Eigen::VectorXd& x,
                                        const std::vector<measurement_sigma>& unit,
                                        std::size_t minimum_count);

/// Measurements left out that the model predicts at x are fitted again; returns how many.
std::size_t readmit(const setup& s, inclusion& fitted, const Eigen::VectorXd& x);

/// Outliers at x: fitted measurements whose normalised residual sqrt(s / chi2_dof) exceeds
/// `threshold`; the `listed` largest, largest first; and per head and residual (chord, phase)
/// their number, how many are positive and their sum.
struct outlier_scan {
  std::size_t count = 0;
  std::vector<outlier> worst;
  struct signs {
    std::size_t n = 0;
    std::size_t positive = 0;
    double sum_deg = 0;
  };
  std::vector<signs> chord, phase;  ///< per head
};
outlier_scan find_outliers(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x,
                           double chi2_dof, double threshold, std::size_t listed);

/// Calls each(row) for every measurement in order (on the caller's thread).
template <class Each>
void for_each_residual(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x,
                       double chi2_dof, Each each);

/// The slot values at x for a sample: every slot, the free ones from x.
void slots_at(const setup& s, const Eigen::VectorXd& x, const telemetry_sample& sample,
              double* head_block, double* earth_block);

/// The residuals (deg) of one measurement at the given blocks; false when the model cannot
/// predict it.
bool residuals_deg(const setup& s, const observation& o, const double* head_block,
                   const double* earth_block, double& chord_deg, double& phase_deg);

template <class Each>
void for_each_residual(const setup& s, const inclusion& fitted, const Eigen::VectorXd& x,
                       double chi2_dof, Each each) {
  double head[head_parameter_count], earth[earth_parameter_count];
  for (std::size_t i = 0; i < s.observations.size(); ++i) {
    const observation& o = s.observations[i];
    residual_row row{&o, fitted[i] != 0, false, 0, 0, 0};
    slots_at(s, x, o.sample, head, earth);
    row.predicted = residuals_deg(s, o, head, earth, row.chord_deg, row.phase_deg);
    if (row.predicted) {
      const measurement_sigma& sigma = s.sigma[o.sample.head];
      const double zc = row.chord_deg / sigma.chord_deg, zp = row.phase_deg / sigma.phase_deg;
      row.normalised = std::sqrt((zc * zc + zp * zp) / chi2_dof);
    }
    each(row);
  }
}

}  // namespace conescan::calibration::passes
