// What one head senses in a benchmark scene (zero true attitude, so roll and pitch are the
// errors), and the last step of every method: roll and pitch of the sensed nadir (MODEL §2).
#pragma once

#include "accuracy/head_sample.hpp"
#include "conescan/attitude.hpp"
#include "conescan/processing.hpp"

namespace conescan::accuracy {

/// What one head senses (rad).
template <class T>
struct head_outcome {
  T eta_err;  ///< eta_s - eta, sensed minus true (MODEL §1)
  T roll;
  T pitch;
  status state;

  static head_outcome failed(status s) noexcept {
    return {not_a_number<T>(), not_a_number<T>(), not_a_number<T>(), s};
  }
};

/// The outcome of a processed head: its eta error and the roll and pitch of its sensed nadir.
template <class T>
head_outcome<T> outcome_of(const head_sample<T>& s, const head_estimate<T>& estimate) noexcept {
  if (estimate.state != status::ok) return head_outcome<T>::failed(estimate.state);
  const roll_pitch<T> sensed = roll_pitch_from_nadir(estimate.nadir);
  return {T(estimate.eta_s - s.eta), sensed.roll, sensed.pitch, status::ok};
}

}  // namespace conescan::accuracy
