// The calibration on board (MODEL §11): a head's calibrated parameters, as conescan-fit estimates
// them, turned into the correction of its measured crossings. The rule is the paper's
// "elimination by simple subtraction of the modelled errors": the scan model (MODEL §5) predicts
// the chord and the phase the head measures with its calibrated errors and those an ideal head
// (no misalignment, no biases) measures at the same geometry; the two differences, as errors of
// the two crossings, are subtracted from the measured crossings before the processing.
//
// This file is that rule's one home: conescan-sim --apply (src/scene_calibration/
// fit_correction.cpp, at the scene's true geometry), the calibration's forward model (the
// predictions, src/scene_calibration/scene_model.hpp, in double and ceres::Jet) and flight code
// (at its own estimate of the nadir; include/conescan/conescan.h's conescan_correct_f/_d) all
// call it, so that a flight computer given the same geometry corrects bit for bit as the CLI
// does (tests/scene_calibration/test_flight_calibration.cpp).
//
// Units as conescan-fit writes them: the parameters in degrees, the degree being the double
// nearest pi/180 (calibration_degree); the arithmetic is the fit's, in degrees, then turned
// into radians for the crossings.
#pragma once

#include "conescan/earth_disk.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/measurement_errors.hpp"
#include "conescan/misalignment_components.hpp"

namespace conescan {

/// One degree in rad as the calibration scales its parameters: the double nearest pi/180, in T.
template <class T>
T calibration_degree() noexcept {
  return T(pi<double>() / 180.0);
}

/// What a calibration estimates of a head's cone (deg; MODEL §4, §11): the misalignment by its
/// components x = sigma cos phi_A, y = sigma sin phi_A (smooth at sigma = 0), and the cone-angle
/// bias (the true half-apex angle is the nominal gamma + dgamma).
template <class T>
struct cone_calibration {
  T misalignment_x_deg;
  T misalignment_y_deg;
  T dgamma_deg;
};

/// A head's calibrated parameters (deg): its cone's, and the crossing biases (each measured
/// crossing azimuth is the true one plus bias_in, Earth-in, or bias_out, Earth-out; MODEL §11).
template <class T>
struct head_calibration {
  cone_calibration<T> cone;
  T bias_in_deg;
  T bias_out_deg;
};

/// A chord W and a phase m in degrees, or the status saying why there are none (then both 0).
template <class T>
struct chord_phase_deg {
  T chord_deg;
  T phase_deg;
  status state;
};

/// The chord and phase (deg) of crossings; a failed status passes through.
template <class T>
chord_phase_deg<T> chord_phase_deg_of(const crossings<T>& c) noexcept {
  if (c.state != status::ok) return {T(0), T(0), c.state};
  const T degree = calibration_degree<T>();
  return {T(c.chord() / degree), T(c.phase() / degree), status::ok};
}

/// The chord and phase a head of nominal cone gamma_rad with the calibrated cone `cone` measures
/// on a sphere (the scan model's closed form, component_crossings_sphere): the unit true nadir in
/// scan-frame components, the disk by the sine and cosine of its radius. Statuses: the scan
/// model's (invalid, miss, engulfed, grazing). Before the crossing biases.
template <class T>
chord_phase_deg<T> predicted_chord_phase(const T& gamma_rad, const cone_calibration<T>& cone,
                                         const vec3<T>& nadir_scan,
                                         const disk_trig<T>& disk) noexcept {
  const T degree = calibration_degree<T>();
  return chord_phase_deg_of(component_crossings_sphere(
      T(gamma_rad + cone.dgamma_deg * degree), T(cone.misalignment_x_deg * degree),
      T(cone.misalignment_y_deg * degree), nadir_scan, disk));
}

/// The same on an ellipsoid expressed in the head's scan frame (component_crossings_ellipsoid:
/// the Newton closed form, invalid where it does not settle).
template <class T>
chord_phase_deg<T> predicted_chord_phase(const T& gamma_rad, const cone_calibration<T>& cone,
                                         const ellipsoid_horizon<T>& surface_scan) noexcept {
  const T degree = calibration_degree<T>();
  return chord_phase_deg_of(component_crossings_ellipsoid(
      T(gamma_rad + cone.dgamma_deg * degree), T(cone.misalignment_x_deg * degree),
      T(cone.misalignment_y_deg * degree), surface_scan));
}

/// The measurement with the crossing biases (deg): each crossing azimuth moves by its bias, so
/// the chord by bias_out - bias_in and the phase by (bias_in + bias_out) / 2.
template <class T>
chord_phase_deg<T> with_crossing_biases(const chord_phase_deg<T>& m, const T& bias_in_deg,
                                        const T& bias_out_deg) noexcept {
  return {T(m.chord_deg + bias_out_deg - bias_in_deg),
          T(m.phase_deg + (bias_in_deg + bias_out_deg) / T(2)), m.state};
}

/// A phase difference (deg) brought into [-180, 180] by whole turns.
template <class T>
T phase_difference_deg(const T& difference_deg) noexcept {
  using std::round;
  const T turns = round(difference_deg / T(360));
  return T(difference_deg - T(360) * turns);
}

/// The rule: the measured crossings less the modelled errors, the chord's and the phase's
/// differences between the calibrated head's prediction (with its crossing biases) and the ideal
/// head's, as errors of the two crossings (phi_in by phase error - chord error / 2, phi_out by
/// phase error + chord error / 2). A failed measurement passes through; a prediction that fails
/// gives its status (the calibrated one's first). Statuses otherwise with_crossing_noise's
/// (invalid, grazing: a correction that closes the chord).
template <class T>
crossings<T> corrected_crossings(const crossings<T>& measured, const chord_phase_deg<T>& modelled,
                                 const chord_phase_deg<T>& ideal) noexcept {
  if (measured.state != status::ok) return measured;
  if (modelled.state != status::ok) return crossings<T>::failed(modelled.state);
  if (ideal.state != status::ok) return crossings<T>::failed(ideal.state);
  const T degree = calibration_degree<T>();
  const T chord_error = (modelled.chord_deg - ideal.chord_deg) * degree;
  const T phase_error = phase_difference_deg(T(modelled.phase_deg - ideal.phase_deg)) * degree;
  return with_crossing_noise(measured, T(-(phase_error - chord_error / T(2))),
                             T(-(phase_error + chord_error / T(2))));
}

/// The correction of a head's measured crossings on a sphere: its nominal cone gamma_rad, its
/// calibration, the geometry it sees (the unit nadir in scan-frame components, the disk of the
/// calibrated horizon: R + horizon-km from the orbit radius). conescan-sim --apply passes the
/// scene's true nadir; flight code its own estimate (the correction changes little with it:
/// docs/FLIGHT_SOFTWARE.md). Statuses: corrected_crossings's.
template <class T>
crossings<T> calibrated_crossings(const crossings<T>& measured, const T& gamma_rad,
                                  const head_calibration<T>& calibration, const vec3<T>& nadir_scan,
                                  const disk_trig<T>& disk) noexcept {
  if (measured.state != status::ok) return measured;
  const chord_phase_deg<T> modelled =
      with_crossing_biases(predicted_chord_phase(gamma_rad, calibration.cone, nadir_scan, disk),
                           calibration.bias_in_deg, calibration.bias_out_deg);
  const chord_phase_deg<T> ideal =
      predicted_chord_phase(gamma_rad, cone_calibration<T>{T(0), T(0), T(0)}, nadir_scan, disk);
  return corrected_crossings(measured, modelled, ideal);
}

/// The same on an ellipsoid expressed in the head's scan frame.
template <class T>
crossings<T> calibrated_crossings(const crossings<T>& measured, const T& gamma_rad,
                                  const head_calibration<T>& calibration,
                                  const ellipsoid_horizon<T>& surface_scan) noexcept {
  if (measured.state != status::ok) return measured;
  const chord_phase_deg<T> modelled =
      with_crossing_biases(predicted_chord_phase(gamma_rad, calibration.cone, surface_scan),
                           calibration.bias_in_deg, calibration.bias_out_deg);
  const chord_phase_deg<T> ideal =
      predicted_chord_phase(gamma_rad, cone_calibration<T>{T(0), T(0), T(0)}, surface_scan);
  return corrected_crossings(measured, modelled, ideal);
}

}  // namespace conescan
