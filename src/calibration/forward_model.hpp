// The interface between the estimator and a forward model: what a model is given (which row and
// head, the parameters as scalars of type T) and what it returns (the predicted chord and phase
// with a status). The estimator calls it with T = double (values) and T = parameter_jet (values
// with their derivatives: Ceres' Jet, automatic differentiation), so a model is written once as a
// template over T (the core's head model is scalar-generic for this) and wrapped by
// forward_model_of<Model>, which instantiates both.
//
// The contract for a model (tests/scene_calibration/test_calibration_engine.cpp checks it with an
// analytic one):
// - predict<T>(sample, head, earth) returns, for head sample.head at telemetry row sample.row
//   (time sample.t_s), the chord W = phi_out - phi_in in (0, 360) deg and the phase
//   (phi_in + phi_out)/2 in deg (any turn: the estimator compares phases modulo 360) that the
//   head would measure with these parameters, before the crossing biases (the estimator adds
//   those: with_crossing_biases, conescan/head_calibration.hpp), with status ok; any other
//   status when it cannot (miss, engulfed, grazing, invalid: the estimator then drops the row
//   at the start, or rejects a step that leads there).
// - It is smooth in every parameter it is given, in particular in the misalignment's two
//   components at sigma = 0 (misalignment.hpp turns them into the optical axis without the
//   square root whose derivative is infinite there).
// - Everything that does not depend on the parameters (the orbit, the attitude, the Sun) is
//   computed once, in double, before the fit, and looked up by sample.row: predict only does
//   the parameter-dependent part.
// - predict is const and safe to call from several threads at once (the fit's passes evaluate
//   the measurements on fit_options::threads threads).
#pragma once

#include <ceres/jet.h>

#include <cmath>
#include <cstddef>

#include "calibration/parameters.hpp"
#include "conescan/head_calibration.hpp"
#include "conescan/status.hpp"

namespace conescan::calibration {

/// One head in one telemetry row: where a measurement was (or would be) taken.
struct telemetry_sample {
  std::size_t row = 0;   ///< 0-based index of the telemetry row (the model's geometry index)
  double t_s = 0;        ///< the row's time, s from the scene's epoch
  std::size_t head = 0;  ///< 0-based head index
};

/// A measured chord and phase of one head in one row.
struct observation {
  telemetry_sample sample;
  double chord_deg = 0;  ///< in (0, 360)
  double phase_deg = 0;
};

/// A head's parameters that change what the head measures before its crossing biases: its cone
/// (deg; the core's cone_calibration, which the on-board correction reads too,
/// conescan/head_calibration.hpp: the misalignment by its components sigma cos phi_A and
/// sigma sin phi_A, MODEL §4's A leaning towards phi_A by sigma, smooth at sigma = 0 where phi_A
/// is undefined, and the cone-angle bias), and its sensor physics (MODEL §12), read only by a
/// head that runs the chain (NaN otherwise: parameters.hpp).
template <class T>
struct head_geometry : cone_calibration<T> {
  T tau_ms;     ///< the detector's time constant (ms)
  T threshold;  ///< the locator's threshold
};

/// The Earth's parameters (km), as the scene options of the same names define them.
template <class T>
struct earth_geometry {
  T horizon_km;          ///< h0
  T horizon_pole_km;     ///< the apparent horizon's pole term
  T horizon_shift_km;    ///< its season term
  T radiance_offset_km;  ///< the limb's 50 % height above the horizon surface (MODEL §12)
  T radiance_scale_km;   ///< the limb's scale height H
};

/// What a head would measure: chord W and phase m (deg), or a status saying why not.
template <class T>
using predicted_measurement = chord_phase_deg<T>;

/// The scalar of derivatives: a value with its derivatives with respect to the 12 parameters a
/// measurement can depend on (its head's 7 and the Earth's 5).
inline constexpr int jet_size = static_cast<int>(head_parameter_count + earth_parameter_count);
using parameter_jet = ceres::Jet<double, jet_size>;

/// The model as the estimator sees it. Implement a class with a template predict<T> and wrap it
/// in forward_model_of rather than deriving from this directly.
class forward_model {
 public:
  virtual ~forward_model() = default;
  virtual predicted_measurement<double> predict(const telemetry_sample& sample,
                                                const head_geometry<double>& head,
                                                const earth_geometry<double>& earth) const = 0;
  virtual predicted_measurement<parameter_jet> predict(
      const telemetry_sample& sample, const head_geometry<parameter_jet>& head,
      const earth_geometry<parameter_jet>& earth) const = 0;
};

/// A forward_model from any class with
///   template <class T> predicted_measurement<T> predict(const telemetry_sample&,
///       const head_geometry<T>&, const earth_geometry<T>&) const;
template <class Model>
class forward_model_of final : public forward_model {
 public:
  explicit forward_model_of(Model model) : model_(std::move(model)) {}
  const Model& model() const noexcept { return model_; }

  predicted_measurement<double> predict(const telemetry_sample& sample,
                                        const head_geometry<double>& head,
                                        const earth_geometry<double>& earth) const override {
    return model_.template predict<double>(sample, head, earth);
  }
  predicted_measurement<parameter_jet> predict(
      const telemetry_sample& sample, const head_geometry<parameter_jet>& head,
      const earth_geometry<parameter_jet>& earth) const override {
    return model_.template predict<parameter_jet>(sample, head, earth);
  }

 private:
  Model model_;
};

// The crossing biases are applied by the core's with_crossing_biases (head_calibration.hpp): the
// one place, which the estimator's residuals and a correction that subtracts a fit (--apply) both
// call.

/// The value part of a scalar (itself for double, the Jet's value otherwise).
inline double value_of(double x) noexcept {
  return x;
}
template <int N>
double value_of(const ceres::Jet<double, N>& x) noexcept {
  return x.a;
}

/// An angle difference brought into [-180, 180] deg by whole turns (the turns carry no
/// derivative), so that phases compare modulo 360.
template <class T>
T wrapped_difference_deg(const T& difference_deg) {
  const double turns = std::round(value_of(difference_deg) / 360.0);
  return T(difference_deg - 360.0 * turns);
}

}  // namespace conescan::calibration

namespace ceres {

/// A Jet's value as a long double, for the counts and indices the core derives from a scalar
/// (conescan/scalar.hpp's long_double_value, found here by argument-dependent lookup): they
/// carry no derivative.
template <class T, int N>
long double long_double_value(const Jet<T, N>& x) noexcept {
  return static_cast<long double>(x.a);
}

}  // namespace ceres
