// Detector noise and telemetry quantisation of one head's measurement (the error budget).
#pragma once

#include "conescan/crossings.hpp"

namespace conescan {

/// The crossings with detector noise added: each azimuth moves by its own draw (rad). Noise on
/// each crossing, not on the chord, because the detector times each transition separately: the
/// chord's noise is then sqrt(2) times a crossing's, the phase's 1/sqrt(2). A failed measurement
/// stays failed. Non-finite draws (or azimuths that overflow) give status invalid; noise that
/// closes the chord, or opens it to a full turn or more, leaves no pair of crossings: grazing
/// (MODEL §7, a chord near 0 or 360 deg), so an ok chord stays in (0, 2 pi).
template <class T>
crossings<T> with_crossing_noise(const crossings<T>& c, const T& noise_in,
                                 const T& noise_out) noexcept {
  if (c.state != status::ok) return c;
  if (!is_finite(noise_in) || !is_finite(noise_out)) return crossings<T>::failed(status::invalid);
  crossings<T> noisy = c;
  noisy.phi_in += noise_in;
  noisy.phi_out += noise_out;
  if (!is_finite(noisy.phi_in) || !is_finite(noisy.phi_out))
    return crossings<T>::failed(status::invalid);
  const T chord = noisy.chord();
  if (!(chord > T(0)) || !(chord < T(2) * pi<T>())) return crossings<T>::failed(status::grazing);
  return noisy;
}

/// The crossings as telemetry reports them: the chord W and the phase m each rounded to the
/// nearest multiple of lsb (rad; round half away from zero), then phi_in/out = m -+ W/2. The
/// phase is reduced to (-pi, pi] first, as a telemetry counter counts steps within one turn and
/// the CSV reports it (MODEL §1): the reported phase is a whole number of steps even when lsb
/// does not divide a turn (rounding first and wrapping after moved it off the grid);
/// where the nearest step lies beyond +-pi the phase takes the last step inside.
/// lsb = 0 leaves the crossings unchanged; a negative or non-finite lsb is invalid, and so is
/// one so small that W / lsb overflows (denormal lsb). A chord that rounds to 0 or to a full
/// turn, or that the azimuths m -+ W/2 cannot hold apart, is grazing.
template <class T>
crossings<T> quantised(const crossings<T>& c, const T& lsb) noexcept {
  using std::round;
  if (c.state != status::ok || lsb == T(0)) return c;
  if (!is_finite(lsb) || !(lsb > T(0))) return crossings<T>::failed(status::invalid);
  const T chord_steps = round(c.chord() / lsb);
  T phase_steps = round(wrap_pi(c.phase()) / lsb);
  if (!is_finite(chord_steps) || !is_finite(phase_steps))
    return crossings<T>::failed(status::invalid);
  if (phase_steps * lsb > pi<T>()) phase_steps -= T(1);
  if (phase_steps * lsb <= -pi<T>()) phase_steps += T(1);
  const T chord = lsb * chord_steps;
  const T phase = lsb * phase_steps;
  const crossings<T> q{phase - chord / T(2), phase + chord / T(2), status::ok, c.iterations};
  // The chord as the azimuths hold it: a step far below the phase's ulp rounds both azimuths to
  // the phase (found by fuzz_core: a chord of 5e-32 rad at a phase of 2e-16 rad became 0).
  if (!(q.chord() > T(0)) || !(q.chord() < T(2) * pi<T>()))
    return crossings<T>::failed(status::grazing);
  return q;
}

}  // namespace conescan
