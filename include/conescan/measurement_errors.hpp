// Detector noise and telemetry quantisation of one head's measurement (issue 7's error budget).
#pragma once

#include "conescan/crossings.hpp"

namespace conescan {

/// The crossings with detector noise added: each azimuth moves by its own draw (rad). Noise on
/// each crossing, not on the chord, because the detector times each transition separately: the
/// chord's noise is then sqrt(2) times a crossing's, the phase's 1/sqrt(2). A failed measurement
/// stays failed. Non-finite draws give status invalid.
template <class T>
crossings<T> with_crossing_noise(const crossings<T>& c, const T& noise_in,
                                 const T& noise_out) noexcept {
  if (c.state != status::ok) return c;
  if (!is_finite(noise_in) || !is_finite(noise_out)) return crossings<T>::failed(status::invalid);
  crossings<T> noisy = c;
  noisy.phi_in += noise_in;
  noisy.phi_out += noise_out;
  if (!(noisy.phi_out > noisy.phi_in)) return crossings<T>::failed(status::grazing);
  return noisy;
}

/// The crossings as telemetry reports them: chord W and phase m each rounded to the nearest
/// multiple of lsb (rad; round half away from zero), then phi_in/out = m -+ W/2. lsb = 0 leaves
/// them unchanged; a negative or non-finite lsb is invalid. A chord that rounds to 0 is grazing.
template <class T>
crossings<T> quantised(const crossings<T>& c, const T& lsb) noexcept {
  using std::round;
  if (c.state != status::ok || lsb == T(0)) return c;
  if (!is_finite(lsb) || !(lsb > T(0))) return crossings<T>::failed(status::invalid);
  T chord = lsb * round(c.chord() / lsb);
  T phase = lsb * round(c.phase() / lsb);
  if (!(chord > T(0))) return crossings<T>::failed(status::grazing);
  return {phase - chord / T(2), phase + chord / T(2), status::ok, c.iterations};
}

}  // namespace conescan
