// What the detector of one head measures in one scan: the Earth-in and Earth-out azimuths.
#pragma once

#include "conescan/status.hpp"

namespace conescan {

/// Optics of one head (rad): half-apex cone angle gamma (nominal, what the electronics assume),
/// misalignment sigma of the optical axis from the spin axis, and its azimuth phi_a about S.
template <class T>
struct head_optics {
  T gamma;
  T sigma;
  T phi_a;
};

/// Earth-in and Earth-out scan azimuths (rad, phi_out > phi_in, phi_out - phi_in < 2 pi).
/// On any status but ok both are NaN. `iterations` counts the root-finder steps (0 for closed
/// forms), reported by conescan-sim --trace.
template <class T>
struct crossings {
  T phi_in;
  T phi_out;
  status state;
  int iterations;

  /// Chord W = phi_out - phi_in and half chord W / 2 (MODEL §6).
  T chord() const noexcept { return phi_out - phi_in; }
  T half_chord() const noexcept { return (phi_out - phi_in) / T(2); }
  /// Phase m = (phi_in + phi_out) / 2: the sensed azimuth of the nadir about S (MODEL §6).
  T phase() const noexcept { return (phi_in + phi_out) / T(2); }

  /// The crossings of a telemetry's chord W and phase m (rad): phi_in = m - W/2,
  /// phi_out = m + W/2, status ok; their range (W in (0, 2 pi), finite) is the processing's to
  /// check (process_head says invalid).
  static crossings from_chord_phase(const T& chord, const T& phase) noexcept {
    const T half = chord / T(2);
    return {T(phase - half), T(phase + half), status::ok, 0};
  }

  static crossings failed(status s) noexcept {
    return {not_a_number<T>(), not_a_number<T>(), s, 0};
  }
};

}  // namespace conescan
