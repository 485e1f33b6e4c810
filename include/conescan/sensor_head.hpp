// One sensor head end to end (MODEL §4-§6), built once from its mounting, optics and measurement
// errors, with its pipeline as named steps:
//   1. truth crossings   bias_crossings (sphere, the paper's model) | scan_crossings (sphere, or
//                        the ellipsoid seen from the satellite)      scan_model.hpp, bias_model.hpp
//   2. measurement       measured: detector noise (the caller's draws), telemetry steps
//                                                                    measurement_errors.hpp
//   3. processing        process: chord inversion, sensed nadir      processing.hpp
//   4. roll and pitch    roll_pitch_from_nadir(estimate.nadir)       attitude.hpp
// The scene (src/simulation/simulation.cpp), the benchmark (bench/), the accuracy tests and the
// flight-software example call these steps; everything that depends on the head alone (the scan
// frame, the scan circle about the optical axis, the cosines and sines of gamma and eta0) is
// computed here once, not per scan; the bias model's cone angle is the caller's to keep (a
// head used with the scan model does not pay for it).
//
// Templated on the scalar like the rest of the core; the truth crossings and the processing also
// compile for ceres::Jet (the calibration differentiates through them;
// tests/core/test_sensor_head.cpp). Noise draws are not made here: the caller passes them (the
// scene's counter-based generator), so the core stays free of state and of <random>.
#pragma once

#include "conescan/bias_model.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/measurement_errors.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_frame.hpp"
#include "conescan/scan_model.hpp"

namespace conescan {

/// A head's measurement errors (rad). 0 switches one off.
template <class T>
struct head_errors {
  T noise;  ///< detector noise, 1 sigma, on each crossing azimuth
  T lsb;    ///< telemetry step of the chord and the phase
};

/// A head's fixed biases (rad, MODEL §11), what a calibration estimates besides the misalignment:
/// the true half-apex angle is gamma + dgamma while the electronics assume gamma, and each
/// measured crossing azimuth is the true one plus bias_in (Earth-in) or bias_out (Earth-out), so
/// the chord moves by bias_out - bias_in and the phase by (bias_in + bias_out) / 2. 0: none.
template <class T>
struct head_biases {
  T dgamma;
  T bias_in;
  T bias_out;
};

/// One sensor head (MODEL §4): its frame in body axes, its optics, its measurement errors.
template <class T>
class sensor_head {
 public:
  /// From the scan frame in body axes (scan_frame_from_mounting), the optics, the measurement
  /// errors and the attitude envelope of MODEL §7 (rad; both roots of the inversion within it of
  /// eta0 are ambiguous). The state is invalid when the frame is, or the optics lie outside
  /// cone_in_domain, or phi_A or an error is not finite or negative, or the envelope lies
  /// outside [0, pi/2]; every step then returns invalid. `biases` (default none): the truth
  /// crossings use the cone gamma + dgamma, the processing gamma; invalid when gamma + dgamma
  /// leaves cone_in_domain or a bias is not finite.
  sensor_head(const scan_frame<T>& frame_body, const head_optics<T>& optics,
              const head_errors<T>& errors = {T(0), T(0)},
              const T& attitude_envelope = default_attitude_envelope<T>(),
              const head_biases<T>& biases = {T(0), T(0), T(0)}) noexcept
      : frame_(frame_body),
        optics_(optics),
        errors_(errors),
        biases_(biases),
        circle_(scan_circle_of(true_optics())),
        inversion_(head_inversion_of(frame_body, nominal_cos_gamma(), nominal_sin_gamma(),
                                     attitude_envelope)) {
    const bool errors_ok = is_finite(errors.noise) && is_finite(errors.lsb) &&
                           errors.noise >= T(0) && errors.lsb >= T(0);
    const bool biases_ok = is_finite(biases.bias_in) && is_finite(biases.bias_out) &&
                           cone_in_domain(optics.gamma, optics.sigma);
    state_ = frame_body.state == status::ok && circle_.state == status::ok && errors_ok &&
                     biases_ok && attitude_envelope_in_domain(attitude_envelope)
                 ? status::ok
                 : status::invalid;
  }

  /// From the mounting: alpha, beta (rad, MODEL §4).
  static sensor_head from_mounting(const T& alpha, const T& beta, const head_optics<T>& optics,
                                   const head_errors<T>& errors = {T(0), T(0)},
                                   const T& attitude_envelope = default_attitude_envelope<T>(),
                                   const head_biases<T>& biases = {T(0), T(0), T(0)}) noexcept {
    return sensor_head(scan_frame_from_mounting(alpha, beta), optics, errors, attitude_envelope,
                       biases);
  }

  status state() const noexcept { return state_; }
  const scan_frame<T>& frame() const noexcept { return frame_; }
  const head_optics<T>& optics() const noexcept { return optics_; }
  const head_errors<T>& errors() const noexcept { return errors_; }
  const head_biases<T>& biases() const noexcept { return biases_; }
  /// The true scan circle: the cone gamma + dgamma about the optical axis.
  const scan_circle<T>& circle() const noexcept { return circle_; }
  /// The cosines and sines the processing uses (gamma, eta0).
  const head_inversion<T>& inversion() const noexcept { return inversion_; }
  /// Nominal nadir angle of the spin axis (rad): the processing picks the root nearest it.
  T eta0() const noexcept {
    using std::atan2;
    return atan2(inversion_.sin_eta0, inversion_.cos_eta0);
  }

  /// A body-axes vector's components in the head's scan frame (e1, e2, e3).
  vec3<T> in_scan_frame(const vec3<T>& v_body) const noexcept {
    return vec3<T>(dot(frame_.e1, v_body), dot(frame_.e2, v_body), dot(frame_.e3, v_body));
  }

  /// A surface expressed in body axes (ellipsoid_horizon_of with p and the polar axis in body
  /// axes: one per time step for every head) re-expressed in the head's scan frame.
  ellipsoid_horizon<T> in_scan_frame(const ellipsoid_horizon<T>& surface_body) const noexcept {
    ellipsoid_horizon<T> s = surface_body;
    s.position = in_scan_frame(surface_body.position);
    s.q = in_scan_frame(surface_body.q);
    s.polar = in_scan_frame(surface_body.polar);
    return s;
  }

  // --- 1. Truth crossings ---------------------------------------------------------------------

  /// The bias model's fixed cone angle: psi at the reference pulse (bias_cone_angle, MODEL §5).
  /// Computed on each call: a caller of bias_crossings keeps it (once per head).
  result<T> bias_cone_angle() const noexcept {
    if (state_ != status::ok) return result<T>::bad(status::invalid);
    return conescan::bias_cone_angle(true_optics());
  }

  /// The paper's bias model on a sphere (MODEL §5) with its cone angle psi_bias
  /// (bias_cone_angle()): the true nadir at eta from S and azimuth phi_n about S
  /// (scan_angles_of(frame(), nadir_body)), the disk's angular radius rho (rad).
  crossings<T> bias_crossings(const result<T>& psi_bias, const T& eta, const T& phi_n,
                              const T& rho) const noexcept {
    if (state_ != status::ok) return crossings<T>::failed(status::invalid);
    if (!psi_bias.ok()) return crossings<T>::failed(psi_bias.state);
    return bias_model_crossings(psi_bias.value, eta, phi_n, rho);
  }

  /// The scan model on a sphere in closed form (MODEL §5): the unit true nadir in scan-frame
  /// components (in_scan_frame(nadir_body)), the disk by the sine and cosine of its radius.
  crossings<T> scan_crossings(const vec3<T>& nadir_scan, const disk_trig<T>& disk) const noexcept {
    if (state_ != status::ok) return crossings<T>::failed(status::invalid);
    return scan_model_crossings_sphere(circle_, nadir_scan, disk);
  }

  /// The scan model on an ellipsoid (MODEL §3, §5), the surface in scan-frame components
  /// (in_scan_frame(surface_body)).
  crossings<T> scan_crossings(const ellipsoid_horizon<T>& surface_scan) const noexcept {
    if (state_ != status::ok) return crossings<T>::failed(status::invalid);
    return scan_model_crossings_ellipsoid(circle_, true_optics(), surface_scan);
  }

  // --- 2. Measurement errors ------------------------------------------------------------------

  /// What the detector and the telemetry make of the true crossings: each azimuth moved by its
  /// crossing bias, then by noise x its draw (standard normal draws, the caller's), then the
  /// chord and the phase quantised to the step (measurement_errors.hpp). A head without errors
  /// or biases passes them through.
  crossings<T> measured(const crossings<T>& truth, const T& draw_in,
                        const T& draw_out) const noexcept {
    crossings<T> c = truth;
    // A bias moves a crossing as a noise draw does (same rule, same statuses), only fixed.
    if (biases_.bias_in != T(0) || biases_.bias_out != T(0))
      c = with_crossing_noise(c, biases_.bias_in, biases_.bias_out);
    if (errors_.noise > T(0))
      c = with_crossing_noise(c, T(errors_.noise * draw_in), T(errors_.noise * draw_out));
    return quantised(c, errors_.lsb);
  }

  // --- 3. Processing --------------------------------------------------------------------------

  /// MODEL §6: the measured chord inverted on the assumed disk (root nearest eta0), the sensed
  /// nadir in body axes. Statuses: the crossings' own, invalid, fold, grazing, ambiguous.
  head_estimate<T> process(const crossings<T>& measured,
                           const disk_trig<T>& assumed) const noexcept {
    if (state_ != status::ok && measured.state == status::ok)
      return {not_a_number<T>(), vec3<T>(not_a_number<T>()), status::invalid};
    return process_head(frame_, inversion_, assumed, measured);
  }

 private:
  head_optics<T> true_optics() const noexcept {
    return {T(optics_.gamma + biases_.dgamma), optics_.sigma, optics_.phi_a};
  }
  T nominal_cos_gamma() const noexcept {
    using std::cos;
    return cos(optics_.gamma);
  }
  T nominal_sin_gamma() const noexcept {
    using std::sin;
    return sin(optics_.gamma);
  }

  scan_frame<T> frame_;
  head_optics<T> optics_;
  head_errors<T> errors_;
  head_biases<T> biases_;
  scan_circle<T> circle_;
  head_inversion<T> inversion_;
  status state_ = status::invalid;
};

}  // namespace conescan
