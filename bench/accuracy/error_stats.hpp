// Error of a tested precision against the reference, over a set of scenes (docs/ACCURACY.md).
#pragma once

#include <cmath>
#include <cstddef>

#include "accuracy/head_outcome.hpp"
#include "accuracy/reference_scalar.hpp"

namespace conescan::accuracy {

/// |tested - reference| in degrees. The difference is taken in the reference scalar, into
/// which float, double and long double convert exactly.
template <class T>
double error_deg(const T& tested, const reference_scalar& reference) {
  using std::abs;
  const reference_scalar difference = abs(reference_scalar(tested) - reference);
  return static_cast<double>(rad_to_deg(difference));
}

/// The eta error and the attitude (roll, pitch) error of one head sample against the reference.
struct sample_error {
  double eta_deg;
  double attitude_deg;  ///< max of the roll and the pitch errors
};

template <class T>
sample_error sample_error_of(const head_outcome<T>& tested,
                             const head_outcome<reference_scalar>& reference) {
  const double roll = error_deg(tested.roll, reference.roll);
  const double pitch = error_deg(tested.pitch, reference.pitch);
  return {error_deg(tested.eta_err, reference.eta_err), roll > pitch ? roll : pitch};
}

/// Accumulated over scenes. Errors are compared only where both statuses are ok; where they
/// differ the scene is counted instead (a boundary decided the other way by rounding).
struct error_stats {
  std::size_t compared = 0;       ///< both ok
  std::size_t false_ok = 0;       ///< tested ok, reference not
  std::size_t false_refusal = 0;  ///< reference ok, tested not
  double max_eta_deg = 0;
  double max_attitude_deg = 0;
  double sum_square_eta_deg = 0;
  std::size_t worst_scene = 0;  ///< index of the largest eta error

  double rms_eta_deg() const {
    return compared == 0 ? 0.0 : std::sqrt(sum_square_eta_deg / static_cast<double>(compared));
  }

  template <class T>
  void add(std::size_t scene, const head_outcome<T>& tested,
           const head_outcome<reference_scalar>& reference) {
    const bool tested_ok = tested.state == status::ok;
    const bool reference_ok = reference.state == status::ok;
    if (tested_ok != reference_ok) {
      ++(tested_ok ? false_ok : false_refusal);
      return;
    }
    if (!tested_ok) return;
    const sample_error e = sample_error_of(tested, reference);
    ++compared;
    sum_square_eta_deg += e.eta_deg * e.eta_deg;
    if (e.eta_deg > max_eta_deg) {
      max_eta_deg = e.eta_deg;
      worst_scene = scene;
    }
    if (e.attitude_deg > max_attitude_deg) max_attitude_deg = e.attitude_deg;
  }
};

}  // namespace conescan::accuracy
